// The event calendar against a plainly correct reference (a sorted set of
// (time, id)): the same order under random updates spanning many years and
// time scales, as a cooling gas produces (DynamO's sorter tests do the same).
#include "simulate/event_calendar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "simulate/random.h"

namespace coolgas {
namespace {

TEST(EventCalendar, PopsInTheSameOrderAsASortedSet) {
  const int n = 1000;
  Random rng(42);
  std::vector<double> times(n);
  for (auto& t : times) t = rng.uniform();
  EventCalendar cal;
  cal.reset(&times, 0.0);
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
    cal.update(top);
    const int other = int(rng.below(n));
    ref.erase({times[other], other});
    if (rng.uniform() < 0.05) {
      times[other] = std::numeric_limits<double>::infinity();
    } else {
      times[other] = now + scale * rng.uniform();
      ref.insert({times[other], other});
    }
    cal.update(other);
  }
  EXPECT_GT(cal.years(), 10);  // the test crossed many calendar years
}

TEST(EventCalendar, TiesGoToTheSmallerId) {
  std::vector<double> times = {2.0, 1.0, 1.0, 3.0};
  EventCalendar cal;
  cal.reset(&times, 0.0);
  EXPECT_EQ(cal.top(), 1);
  times[1] = std::numeric_limits<double>::infinity();
  cal.update(1);
  EXPECT_EQ(cal.top(), 2);
}

TEST(EventCalendar, EmptyCalendarHasNoTop) {
  std::vector<double> times(3, std::numeric_limits<double>::infinity());
  EventCalendar cal;
  cal.reset(&times, 0.0);
  EXPECT_EQ(cal.top(), -1);
}

}  // namespace
}  // namespace coolgas
