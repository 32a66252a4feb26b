// The event calendar: at most one pending event per particle, found in O(1)
// amortised time (Paul 2007, J. Comput. Phys. 221, 615: "A complexity O(1)
// priority queue for event driven molecular dynamics simulations").
//
// Contract:
//   - schedule(i, e) sets particle i's single event, replacing any earlier
//     one; an event at +inf is no event. assign() sets an event without
//     queueing it, for bulk set-up followed by reset().
//   - top() returns the particle with the earliest (time, id); ties go to the
//     smaller id, so the order is deterministic. The id is the particle's
//     index, or the key break_ties_by() gives (an engine whose slots move).
//   - an event time is never earlier than the time of the last top() (events
//     are never scheduled in the past).
//
// How: time ahead of the current instant is cut into nb buckets of width Δ
// (one "year" = nb Δ). Events in future buckets sit unsorted in doubly
// linked lists; events beyond the year are only marked and counted as in the
// overflow (a new year finds them by a scan); only the current bucket's
// events are kept sorted, in a small binary heap. When the year runs out the
// overflow is redistributed into a new year whose Δ is
// chosen from the pending events themselves, so the width follows the gas as
// it cools (a fixed width degrades badly when collision times grow by 10^6).
// Each particle's event and its list links share one 32-byte record: an
// event costs one cache miss, not five.
#pragma once
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "simulate/engine/state_archive.h"

namespace coolgas {

enum class EventKind {
  kNone,       // nothing scheduled (time +inf)
  kCollision,  // with partner()
  kCrossing,   // of face() of the particle's cell (cell_grid.h numbers the faces)
};

// One particle's next event. Kind, partner and face share one 32-bit code so
// that an event stays 16 bytes (two calendar entries per cache line): the
// code is the partner (>= 0), kNoCode, or kFirstFaceCode - face.
class Event {
 public:
  Event() = default;
  // A time alone (engines that keep what happens beside the calendar).
  explicit Event(double t) : time(t) {}
  static Event collision(double t, int partner, std::uint32_t partner_count) { return {t, partner, partner_count}; }
  static Event crossing(double t, int face) { return {t, kFirstFaceCode - face, 0}; }

  EventKind kind() const {
    return code_ >= 0 ? EventKind::kCollision : (code_ == kNoCode ? EventKind::kNone : EventKind::kCrossing);
  }
  bool is_collision() const { return code_ >= 0; }
  int partner() const { return code_; }  // kind() == kCollision only
  int face() const { return kFirstFaceCode - code_; }  // kind() == kCrossing only

  double time = std::numeric_limits<double>::infinity();
  std::uint32_t partner_count = 0;  // the partner's collision count when predicted

 private:
  static constexpr std::int32_t kNoCode = -1, kFirstFaceCode = -2;
  Event(double t, std::int32_t code, std::uint32_t count) : time(t), partner_count(count), code_(code) {}
  std::int32_t code_ = kNoCode;
};
static_assert(sizeof(Event) == 16, "two calendar entries per cache line");

class EventCalendar {
 public:
  // Empties the calendar for n particles; every event at +inf.
  void resize(std::size_t n);
  void assign(int particle, const Event& e) { entry_[particle].event = e; }
  // Queues every finite event, with the year starting at `now`.
  void reset(double now);
  void schedule(int particle, const Event& e);
  // Ties between equal times go to the smaller key[particle], not the smaller
  // index: the order stays that of ids when slots are renumbered. key must
  // outlive the calendar and hold distinct values for the particles with events.
  void break_ties_by(const std::int32_t* key) { tie_key_ = key; }
  const Event& event(int particle) const { return entry_[particle].event; }
  // The particle with the earliest event; -1 if there are no events.
  int top();
  // The particles likely to come due after top() (its children in the heap,
  // -1 where there are none): the engine prefetches their data early.
  int runner_up(int k) const { return k + 1 < int(heap_.size()) ? heap_[std::size_t(k) + 1] : -1; }
  void prefetch_event(int particle) const { __builtin_prefetch(&entry_[std::size_t(particle)]); }
  // What rescheduling `particle` will write besides its own entry: its list
  // neighbours (or its bucket's head), to unlink it; only prefetches, so a
  // link that changes meanwhile costs nothing but the miss.
  void prefetch_unlink(int particle) const {
    const Entry& e = entry_[std::size_t(particle)];
    if (e.where < 0 || e.where == nb_) return;  // in the heap, the overflow or nowhere: nothing far away to touch
    __builtin_prefetch(e.prev != kNone ? static_cast<const void*>(&entry_[std::size_t(e.prev)])
                                       : static_cast<const void*>(&heads_[std::size_t(e.where)]));
    if (e.next != kNone) __builtin_prefetch(&entry_[std::size_t(e.next)]);
  }
  // The head of the list an event at time t goes to (what inserting it reads first).
  void prefetch_insert(double t) const {
    const double offset = (t - base_) * inv_width_;
    if (offset >= double(current_) + 1.0 && offset < double(nb_)) __builtin_prefetch(&heads_[std::size_t(offset)]);
  }

  // Every internal field, under names starting with `prefix` (checkpoints:
  // the restored calendar returns the same events in the same order).
  void save(StateWriter& out, const std::string& prefix) const;
  // load() checks every index, link and count (a crafted or damaged file
  // is refused through in.fail(), naming it, never trusted).
  void load(const StateReader& in, const std::string& prefix);
  // Whether an event is well formed for n particles: a time that is not NaN,
  // a partner in 0..n-1 or a face in 0..5 (checkpoints: kept events too).
  static bool event_in_range(const Event& e, std::int64_t n);
  // Whether every queued event is at `now` or later (the contract's "never
  // in the past", for a calendar loaded from a checkpoint).
  bool queued_from(double now) const;
  std::size_t size() const { return entry_.size(); }

  // Statistics for benchmarks: how many years were started.
  std::int64_t years() const { return years_; }

 private:
  static constexpr std::int32_t kNone = -1;
  struct alignas(32) Entry {
    Event event;
    std::int32_t next = kNone, prev = kNone;  // bucket list links
    // bucket index (0..nb-1), nb for overflow, kNone if absent,
    // or -2 - heap position when in the current bucket's heap.
    std::int32_t where = kNone;
    std::int32_t spare = 0;  // explicit, so an entry has no padding bytes (checkpoints are written byte for byte)
  };
  static_assert(sizeof(Entry) == 32, "two events per cache line");

  double time(int p) const { return entry_[p].event.time; }
  bool earlier(int a, int b) const {
    const double ta = time(a), tb = time(b);
    return ta < tb || (ta == tb && (tie_key_ ? tie_key_[a] < tie_key_[b] : a < b));
  }
  void insert(int p);
  void erase(int p);
  void link(int p, int list);
  void to_overflow(int p);
  void from_overflow(int p);
  void unlink(int p);
  void heap_push(int p);
  void heap_erase(int pos);
  void sift_up(int pos);
  void sift_down(int pos);
  void start_year(double base);
  bool advance_bucket();
  void check_loaded(const StateReader& in, const std::string& prefix) const;

  std::vector<Entry> entry_;
  // nb bucket heads, and one slot that stays kNone (it held the overflow's
  // list head; checkpoints keep their layout).
  std::vector<std::int32_t> heads_;
  std::vector<std::int32_t> heap_;
  double base_ = 0, width_ = 1, inv_width_ = 1;
  std::int32_t nb_ = 1, current_ = 0;
  std::int32_t ahead_ = kNone;  // how far top() has prefetched along the next bucket's list
  std::int64_t overflow_ = 0;  // events marked as in the overflow (where == nb_)
  std::int64_t years_ = 0;
  const std::int32_t* tie_key_ = nullptr;
};

}  // namespace coolgas
