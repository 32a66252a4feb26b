// The event calendar: at most one pending event per particle, found in O(1)
// amortised time (Paul 2007, J. Comput. Phys. 221, 615: "A complexity O(1)
// priority queue for event driven molecular dynamics simulations").
//
// Contract:
//   - the caller owns the event times (the array given to reset()); after
//     changing times[i] it calls update(i), which replaces particle i's event
//     (times[i] = +inf removes it).
//   - top() returns the particle with the earliest (time, id); ties go to the
//     smaller id, so the order is deterministic.
//   - a time given through update() is never earlier than the time of the
//     last top() (events are never scheduled in the past).
//
// How: time ahead of the current instant is cut into nb buckets of width Δ
// (one "year" = nb Δ). Events in future buckets sit unsorted in doubly
// linked lists; events beyond the year in an unsorted overflow list; only the
// current bucket's events are kept sorted, in a small binary heap. When the
// year runs out the overflow is redistributed into a new year whose Δ is
// chosen from the pending events themselves, so the width follows the gas as
// it cools (a fixed width degrades badly when collision times grow by 10^6).
#pragma once
#include <cstdint>
#include <vector>

namespace coolgas {

class EventCalendar {
 public:
  // Empties the calendar for n particles whose event times live in `times`,
  // and inserts every finite event with the year starting at `now`.
  void reset(const std::vector<double>* times, double now);
  void update(int particle);
  // The particle with the earliest event; -1 if there are no events.
  int top();

  // Statistics for benchmarks: how many years were started.
  std::int64_t years() const { return years_; }
  double bucket_width() const { return width_; }

 private:
  static constexpr std::int32_t kNone = -1;
  bool earlier(int a, int b) const {
    const double ta = (*times_)[a], tb = (*times_)[b];
    return ta < tb || (ta == tb && a < b);
  }
  void insert(int p);
  void erase(int p);
  void link(int p, int list);
  void unlink(int p);
  void heap_push(int p);
  void heap_erase(int pos);
  void sift_up(int pos);
  void sift_down(int pos);
  void start_year(double base);
  bool advance_bucket();

  const std::vector<double>* times_ = nullptr;
  std::vector<std::int32_t> next_, prev_;  // bucket list links
  // where_[p]: bucket index (0..nb-1), nb for overflow, kNone if absent,
  // or -2 - heap position when in the current bucket's heap.
  std::vector<std::int32_t> where_;
  std::vector<std::int32_t> heads_;  // nb bucket heads + overflow head
  std::vector<std::int32_t> heap_;
  double base_ = 0, width_ = 1, inv_width_ = 1;
  std::int32_t nb_ = 1, current_ = 0;
  std::int64_t years_ = 0;
};

}  // namespace coolgas
