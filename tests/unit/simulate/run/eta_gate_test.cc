// When the progress line shows its time left (simulate/run/eta_gate.h).
#include "simulate/run/eta_gate.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coolgas {
namespace {

// The early estimates measured live for a 40 s run (15 min, 4 h, 9 h 50 min
// in its first 2-8 %, then about right): hidden until the whole they predict
// settles, and shown once the run has seen 5 % of it.
TEST(EtaGate, WildEarlyEstimatesOfAShortRunAreHidden) {
  EtaGate gate;
  EXPECT_FALSE(gate.show(0.5, NAN));
  EXPECT_FALSE(gate.show(0.8, 900));
  EXPECT_FALSE(gate.show(1.6, 14400));
  EXPECT_FALSE(gate.show(3.2, 35400));
  EXPECT_FALSE(gate.show(3.4, 1000));  // 3.4 s seen of 1003.4 predicted: under 5 %
  EXPECT_TRUE(gate.show(3.6, 68));     // 3.6 s seen of 71.6: 5 %
  EXPECT_TRUE(gate.show(4.0, 3600));   // once shown, it stays shown
}

// A long run's estimate is shown once it has been steady (within a factor
// 1.5) for 5 s, or a quarter of the run so far if that is longer, long
// before 5 % of the run has passed.
TEST(EtaGate, ASteadyEstimateOfALongRunIsShownEarly) {
  EtaGate gate;
  bool shown = false;
  double at = -1;
  for (double t = 1; t <= 60 && !shown; t += 0.5) {
    shown = gate.show(t, 36000 * (1 + 0.1 * std::sin(t)));  // 10 h, +-10 %
    if (shown) at = t;
  }
  EXPECT_TRUE(shown);
  EXPECT_DOUBLE_EQ(at, 6.0);  // 5 s after the first estimate, at t = 1
  EtaGate drifting;
  for (double t = 1; t <= 60; t += 0.5)
    EXPECT_FALSE(drifting.show(t, 36000 * std::exp(0.2 * t))) << t;  // grows by x2.7 every 5 s
}

}  // namespace
}  // namespace coolgas
