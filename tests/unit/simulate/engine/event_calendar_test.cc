// The event calendar against a plainly correct reference (a sorted set of
// (time, id)): the same order under random updates spanning many years and
// time scales, as a cooling gas produces (DynamO's sorter tests do the same).
#include "simulate/engine/event_calendar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "common/random.h"

namespace coolgas {
namespace {

TEST(EventCalendar, PopsInTheSameOrderAsASortedSet) {
  const int n = 1000;
  Random rng(42);
  std::vector<double> times(n);
  for (auto& t : times) t = rng.uniform();
  EventCalendar cal;
  cal.resize(n);
  for (int i = 0; i < n; ++i) cal.assign(i, {times[i]});
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
    cal.schedule(top, {times[top]});
    const int other = int(rng.below(n));
    ref.erase({times[other], other});
    if (rng.uniform() < 0.05) {
      times[other] = std::numeric_limits<double>::infinity();
    } else {
      times[other] = now + scale * rng.uniform();
      ref.insert({times[other], other});
    }
    cal.schedule(other, {times[other]});
  }
  EXPECT_GT(cal.years(), 10);  // the test crossed many calendar years
}

TEST(EventCalendar, TiesGoToTheSmallerId) {
  EventCalendar cal;
  cal.resize(4);
  const double times[] = {2.0, 1.0, 1.0, 3.0};
  for (int i = 0; i < 4; ++i) cal.assign(i, {times[i], 10 + i, 0});
  cal.reset(0.0);
  EXPECT_EQ(cal.top(), 1);
  EXPECT_EQ(cal.event(1).partner, 11);  // the event's payload travels with it
  cal.schedule(1, {std::numeric_limits<double>::infinity()});
  EXPECT_EQ(cal.top(), 2);
}

TEST(EventCalendar, EmptyCalendarHasNoTop) {
  EventCalendar cal;
  cal.resize(3);
  cal.reset(0.0);
  EXPECT_EQ(cal.top(), -1);
}

}  // namespace
}  // namespace coolgas
