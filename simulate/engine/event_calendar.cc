#include "simulate/engine/event_calendar.h"

#include <algorithm>
#include <cmath>

namespace coolgas {

namespace {
// Buckets per particle and target events per bucket. One event per particle
// is pending; with ~2 events per bucket and ~1 bucket per particle the year
// spans about twice the mean time to a particle's next event.
constexpr double kEventsPerBucket = 2.0;
}  // namespace

void EventCalendar::resize(std::size_t n) {
  entry_.assign(n, Entry{});
  std::int32_t nb = 1;
  while (std::size_t(nb) < std::max<std::size_t>(n, 1)) nb *= 2;
  nb_ = nb;
  heads_.assign(std::size_t(nb_) + 1, kNone);
  heap_.clear();
  ahead_ = kNone;
  overflow_ = 0;
}

void EventCalendar::reset(double now) {
  std::fill(heads_.begin(), heads_.end(), kNone);
  heap_.clear();
  ahead_ = kNone;
  // Put everything in overflow, then let start_year distribute it.
  overflow_ = 0;
  for (std::size_t p = 0; p < entry_.size(); ++p) {
    entry_[p].where = kNone;
    if (std::isfinite(time(int(p)))) to_overflow(int(p));
  }
  years_ = 0;
  start_year(now);
}

// Chooses Δ from the pending events: their mean distance ahead of the year's
// start, clipped so a few far-off events (nearly resting particles) cannot
// stretch the buckets, spread at kEventsPerBucket per bucket. The overflow
// is found by a scan of the entries in index order, not by walking its list:
// the list visits them in random order, a cache miss each, three times over
// (the mean, the clipped mean, the redistribution), while the scan streams
// through memory. Which bucket an event sits in never changes the order
// events come due (top()), only how fast they are found.
void EventCalendar::start_year(double base) {
  ++years_;
  const auto n = std::int32_t(entry_.size());
  std::int64_t count = 0;
  double sum = 0;
  for (std::int32_t p = 0; p < n; ++p)
    if (entry_[p].where == nb_) {
      sum += time(p) - base;
      ++count;
    }
  if (count > 0) {
    const double mean = sum / double(count);
    double clipped = 0;
    for (std::int32_t p = 0; p < n; ++p)
      if (entry_[p].where == nb_) clipped += std::min(time(p) - base, 3.0 * mean);
    const double span = 2.0 * clipped / double(count);  // ~ the range holding most events
    const double w = span * kEventsPerBucket / double(count);
    if (w > 0 && std::isfinite(w)) width_ = w;
  }
  // Keep Δ representable relative to the base time (late, slow gases).
  width_ = std::max(width_, std::fabs(base) * 1e-15 + 1e-300);
  inv_width_ = 1.0 / width_;
  base_ = base;
  current_ = 0;
  overflow_ = 0;
  // An event sent back to the overflow (beyond this year too) is marked
  // again at an index already passed, so the scan meets each event once.
  for (std::int32_t p = 0; p < n; ++p)
    if (entry_[p].where == nb_) {
      entry_[p].where = kNone;
      insert(p);  // bucket 0 is the current bucket: insert() puts it in the heap
    }
}

void EventCalendar::insert(int p) {
  const double offset = (time(p) - base_) * inv_width_;
  if (offset < double(current_) + 1.0) {  // in (or, after a new year, before) the current bucket
    heap_push(p);
  } else if (offset >= double(nb_)) {
    to_overflow(p);
  } else {
    link(p, static_cast<int>(offset));
  }
}

void EventCalendar::schedule(int p, const Event& e) {
  erase(p);
  entry_[p].event = e;
  if (std::isfinite(e.time)) insert(p);
}

void EventCalendar::erase(int p) {
  const std::int32_t w = entry_[p].where;
  if (w == kNone) return;
  if (w <= -2) heap_erase(-2 - w);
  else if (w == nb_) from_overflow(p);
  else unlink(p);
}

int EventCalendar::top() {
  while (heap_.empty())
    if (!advance_bucket()) return -1;
  // One more step along the next bucket's list: its entries are in cache by
  // the time it opens, instead of being loaded one miss after another. Only
  // prefetches: a link that changed meanwhile costs nothing but the miss.
  if (ahead_ != kNone) {
    ahead_ = entry_[ahead_].next;
    if (ahead_ != kNone) __builtin_prefetch(&entry_[ahead_]);
  }
  return heap_[0];
}

bool EventCalendar::advance_bucket() {
  while (++current_ < nb_) {
    int p = heads_[current_];
    if (p == kNone) continue;
    heads_[current_] = kNone;
    // The next bucket's events are loaded while this one's are processed (top()).
    ahead_ = current_ + 1 < nb_ ? heads_[current_ + 1] : kNone;
    if (ahead_ != kNone) __builtin_prefetch(&entry_[ahead_]);
    while (p != kNone) {
      const int nxt = entry_[p].next;
      entry_[p].where = kNone;
      heap_push(p);
      p = nxt;
    }
    return true;
  }
  if (overflow_ == 0) return false;  // nothing left anywhere
  start_year(base_ + double(nb_) * width_);
  return true;
}

void EventCalendar::link(int p, int list) {
  Entry& e = entry_[p];
  e.where = list;
  e.prev = kNone;
  e.next = heads_[list];
  if (heads_[list] != kNone) entry_[heads_[list]].prev = p;
  heads_[list] = p;
}

void EventCalendar::to_overflow(int p) {
  entry_[p].where = nb_;
  ++overflow_;
}

void EventCalendar::from_overflow(int p) {
  entry_[p].where = kNone;
  --overflow_;
}

void EventCalendar::unlink(int p) {
  Entry& e = entry_[p];
  if (e.prev != kNone) entry_[e.prev].next = e.next;
  else heads_[e.where] = e.next;
  if (e.next != kNone) entry_[e.next].prev = e.prev;
  e.where = kNone;
}

void EventCalendar::heap_push(int p) {
  heap_.push_back(p);
  entry_[p].where = -2 - std::int32_t(heap_.size() - 1);
  sift_up(int(heap_.size()) - 1);
}

void EventCalendar::heap_erase(int pos) {
  const int p = heap_[pos];
  const int last = heap_.back();
  heap_.pop_back();
  entry_[p].where = kNone;
  if (pos == int(heap_.size())) return;
  heap_[pos] = last;
  entry_[last].where = -2 - pos;
  sift_up(pos);
  sift_down(-2 - entry_[last].where);
}

void EventCalendar::sift_up(int pos) {
  const int p = heap_[pos];
  while (pos > 0) {
    const int parent = (pos - 1) / 2;
    if (!earlier(p, heap_[parent])) break;
    heap_[pos] = heap_[parent];
    entry_[heap_[pos]].where = -2 - pos;
    pos = parent;
  }
  heap_[pos] = p;
  entry_[p].where = -2 - pos;
}

void EventCalendar::sift_down(int pos) {
  const int n = int(heap_.size());
  const int p = heap_[pos];
  while (true) {
    int child = 2 * pos + 1;
    if (child >= n) break;
    if (child + 1 < n && earlier(heap_[child + 1], heap_[child])) ++child;
    if (!earlier(heap_[child], p)) break;
    heap_[pos] = heap_[child];
    entry_[heap_[pos]].where = -2 - pos;
    pos = child;
  }
  heap_[pos] = p;
  entry_[p].where = -2 - pos;
}

namespace {
// The calendar's scalars as one record.
struct CalendarScalars {
  double base, width, inv_width;
  std::int64_t years;
  std::int32_t nb, current, ahead, spare;
};
}  // namespace

void EventCalendar::save(StateWriter& out, const std::string& prefix) const {
  out.put(prefix + "entries", entry_);
  out.put(prefix + "heads", heads_);
  out.put(prefix + "heap", heap_);
  out.put_value(prefix + "scalars", CalendarScalars{base_, width_, inv_width_, years_, nb_, current_, ahead_, 0});
}

void EventCalendar::load(const StateReader& in, const std::string& prefix) {
  entry_ = in.get<Entry>(prefix + "entries");
  heads_ = in.get<std::int32_t>(prefix + "heads");
  heap_ = in.get<std::int32_t>(prefix + "heap");
  const auto s = in.get_value<CalendarScalars>(prefix + "scalars");
  base_ = s.base;
  width_ = s.width;
  inv_width_ = s.inv_width;
  years_ = s.years;
  nb_ = s.nb;
  current_ = s.current;
  ahead_ = s.ahead;
  if (heads_.size() != std::size_t(nb_) + 1) in.fail(prefix + "heads does not match the calendar's bucket count");
  heads_[std::size_t(nb_)] = kNone;  // an earlier build's overflow list: the count below replaces it
  check_loaded(in, prefix);
  overflow_ = std::count_if(entry_.begin(), entry_.end(), [&](const Entry& e) { return e.where == nb_; });
}

// A checkpoint's calendar is trusted by every later top() and schedule():
// an index out of range there is a wild write, a broken list an endless
// loop. So everything is checked once, here, in O(n + buckets).
void EventCalendar::check_loaded(const StateReader& in, const std::string& prefix) const {
  const auto n = std::int64_t(entry_.size());
  const auto fail = [&](const std::string& what) { in.fail(prefix + what); };
  const auto particle = [&](std::int64_t p) { return p >= 0 && p < n; };
  if (nb_ < 1 || current_ < 0 || current_ > nb_)
    fail("scalars: bucket " + std::to_string(current_) + " of " + std::to_string(nb_) + " is out of range");
  if (!(std::isfinite(base_) && std::isfinite(width_) && width_ > 0 && std::isfinite(inv_width_) && inv_width_ > 0))
    fail("scalars: base, width and 1/width must be finite, the widths positive");
  if (ahead_ != kNone && !particle(ahead_)) fail("scalars: prefetch position " + std::to_string(ahead_) + " out of range");
  if (years_ < 0) fail("scalars: a negative year count");
  std::int64_t in_buckets = 0;
  for (std::int64_t p = 0; p < n; ++p) {
    const Entry& e = entry_[std::size_t(p)];
    const bool place_ok = e.where >= kNone ? e.where <= nb_ : -2 - std::int64_t(e.where) < std::int64_t(heap_.size());
    const bool links_ok = (e.next == kNone || particle(e.next)) && (e.prev == kNone || particle(e.prev));
    // Queued exactly when finite: a finite event nowhere would never come due.
    const bool queued_ok = (e.where != kNone) == std::isfinite(e.event.time);
    if (!event_in_range(e.event, n) || !place_ok || !links_ok || !queued_ok)
      fail("entries[" + std::to_string(p) + "] (time " + std::to_string(e.event.time) + ", place " +
           std::to_string(e.where) + ", links " + std::to_string(e.prev) + " " + std::to_string(e.next) +
           ") is out of range or inconsistent");
    in_buckets += e.where >= 0 && e.where < nb_;
  }
  for (std::size_t k = 0; k < heap_.size(); ++k) {
    const std::int32_t p = heap_[k];
    if (!particle(p) || entry_[std::size_t(p)].where != -2 - std::int32_t(k) || (k > 0 && earlier(p, heap_[(k - 1) / 2])))
      fail("heap[" + std::to_string(k) + "] = " + std::to_string(p) + " is out of range or out of heap order");
  }
  // Each bucket list walked from its head: every link consistent, every
  // entry in a bucket met exactly once (so no list loops).
  std::int64_t met = 0;
  for (std::int32_t b = 0; b < nb_; ++b)
    for (std::int32_t p = heads_[std::size_t(b)], prev = kNone; p != kNone; prev = p, p = entry_[std::size_t(p)].next)
      if (!particle(p) || entry_[std::size_t(p)].where != b || entry_[std::size_t(p)].prev != prev || ++met > n)
        fail("bucket " + std::to_string(b) + " lists entry " + std::to_string(p) + " inconsistently");
  if (met != in_buckets)
    fail("the bucket lists hold " + std::to_string(met) + " entries, the entries say " + std::to_string(in_buckets));
}

bool EventCalendar::event_in_range(const Event& e, std::int64_t n) {
  if (std::isnan(e.time)) return false;
  switch (e.kind()) {
    case EventKind::kCollision: return e.partner() < n;
    case EventKind::kCrossing: return e.face() >= 0 && e.face() < 6;
    case EventKind::kNone: return true;
  }
  return false;
}

bool EventCalendar::queued_from(double now) const {
  for (const Entry& e : entry_)
    if (e.where != kNone && !(e.event.time >= now)) return false;
  return true;
}

}  // namespace coolgas
