// The event calendar against a plainly correct reference (a sorted set of
// (time, id)): the same order under random updates spanning many years and
// time scales, as a cooling gas produces (DynamO's sorter tests do the same).
#include "simulate/engine/event_calendar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "common/random.h"
#include "tests/support/saved_state.h"

namespace coolgas {
namespace {

TEST(EventCalendar, PopsInTheSameOrderAsASortedSet) {
  const int n = 1000;
  Random rng(42);
  std::vector<double> times(n);
  for (auto& t : times) t = rng.uniform();
  EventCalendar cal;
  cal.resize(n);
  for (int i = 0; i < n; ++i) cal.assign(i, Event(times[i]));
  cal.reset(0.0);
  std::set<std::pair<double, int>> ref;
  for (int i = 0; i < n; ++i) ref.insert({times[i], i});
  double now = 0;
  for (int step = 0; step < 200000; ++step) {
    const int top = cal.top();
    ASSERT_EQ(top, ref.begin()->second) << "step " << step;
    now = times[top];
    ASSERT_GE(now, 0);
    // Reschedule it, with a time scale that grows like a cooling gas's, and
    // sometimes also reschedule (or remove) another particle.
    const double scale = 1.0 + double(step) / 1000.0;
    ref.erase({times[top], top});
    times[top] = now + scale * rng.uniform() * rng.uniform();
    ref.insert({times[top], top});
    cal.schedule(top, Event(times[top]));
    const int other = int(rng.below(n));
    ref.erase({times[other], other});
    if (rng.uniform() < 0.05) {
      times[other] = std::numeric_limits<double>::infinity();
    } else {
      times[other] = now + scale * rng.uniform();
      ref.insert({times[other], other});
    }
    cal.schedule(other, Event(times[other]));
  }
  EXPECT_GT(cal.years(), 10);  // the test crossed many calendar years
}

TEST(EventCalendar, TiesGoToTheSmallerId) {
  EventCalendar cal;
  cal.resize(4);
  const double times[] = {2.0, 1.0, 1.0, 3.0};
  for (int i = 0; i < 4; ++i) cal.assign(i, Event::collision(times[i], 10 + i, 0));
  cal.reset(0.0);
  EXPECT_EQ(cal.top(), 1);
  EXPECT_EQ(cal.event(1).partner(), 11);  // the event's payload travels with it
  cal.schedule(1, Event{});
  EXPECT_EQ(cal.top(), 2);
}

// An engine whose slots are renumbered (the aggregation engine's) breaks ties
// by its ids: four equal times pop in the order of the keys, not the slots.
TEST(EventCalendar, TiesGoToTheSmallerKeyWhenGivenKeys) {
  EventCalendar cal;
  cal.resize(5);
  const std::int32_t key[] = {7, 3, 9, 1, 5};
  cal.break_ties_by(key);
  for (int i = 0; i < 4; ++i) cal.assign(i, Event(1.0));
  cal.assign(4, Event(0.5));
  cal.reset(0.0);
  for (const int expected : {4, 3, 1, 0, 2}) {
    ASSERT_EQ(cal.top(), expected);
    cal.schedule(expected, Event{});
  }
  EXPECT_EQ(cal.top(), -1);
}

TEST(EventKind, CrossingFaceZeroIsNeitherNoEventNorACollision) {
  EXPECT_EQ(Event{}.kind(), EventKind::kNone);
  for (int face = 0; face < 6; ++face) {
    const Event e = Event::crossing(1.0, face);
    EXPECT_EQ(e.kind(), EventKind::kCrossing);
    EXPECT_EQ(e.face(), face);
  }
  const Event c = Event::collision(1.0, 0, 7);
  EXPECT_EQ(c.kind(), EventKind::kCollision);
  EXPECT_EQ(c.partner(), 0);
  EXPECT_EQ(c.partner_count, 7u);
}

// A calendar saved mid-run and loaded into a fresh one pops the same
// particles in the same order under the same updates (checkpoints).
TEST(EventCalendar, SavedAndLoadedPopsTheSameSequence) {
  const int n = 500;
  Random rng(7);
  EventCalendar a;
  a.resize(n);
  for (int i = 0; i < n; ++i) a.assign(i, Event(rng.uniform()));
  a.reset(0.0);
  auto step = [](EventCalendar& cal, Random& r) {
    const int top = cal.top();
    cal.schedule(top, Event(cal.event(top).time + r.uniform()));
    return top;
  };
  for (int k = 0; k < 3000; ++k) step(a, rng);
  EventCalendar b;
  b.load(test::saved_state_of([&](StateWriter& out) { a.save(out, "c/"); }), "c/");
  Random rb = rng;
  for (int k = 0; k < 20000; ++k) ASSERT_EQ(step(a, rng), step(b, rb)) << "step " << k;
  EXPECT_EQ(a.years(), b.years());
}

TEST(EventCalendar, EmptyCalendarHasNoTop) {
  EventCalendar cal;
  cal.resize(3);
  cal.reset(0.0);
  EXPECT_EQ(cal.top(), -1);
}

}  // namespace
}  // namespace coolgas
