// The run's ETA (simulate/run/run_eta.h) on synthetic runs whose answer is
// known in closed form: C(t) = 1000 t^0.4 collisions (the collision rate of
// a gas with E ~ t^-6/5 falls as sqrt(E) ~ t^-0.6), at 2e5 collisions per
// busy second.
#include "simulate/run/run_eta.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coolgas {
namespace {

constexpr double kRate = 2e5;
double collisions(double t) { return 1000 * std::pow(t, 0.4); }

TEST(RunEta, APowerLawOfCollisionsIsExtrapolatedExactly) {
  RunEta eta(1e6);  // the finite-size regime (2 L^(5/2)) far beyond t_end
  for (int k = -40; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0);
    eta.add({t, collisions(t), collisions(t) / kRate});
  }
  EXPECT_NEAR(eta.collision_rate(), kRate, 1e-9 * kRate);
  EXPECT_NEAR(eta.expected_collisions(1e4), collisions(1e4), 1e-9 * collisions(1e4));
  const double left = (collisions(1e4) - collisions(100)) / kRate;
  EXPECT_NEAR(eta.seconds_left(1e4), left, 1e-9 * left);
}

// L = 10: beyond t = 2 L^(5/2) = 632.5 the exponent is 1 - 1.83/2 = 0.085.
TEST(RunEta, BeyondTheFiniteSizeCrossoverCollisionsGrowAsTheTailSays) {
  RunEta eta(10);
  for (int k = -40; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0);
    eta.add({t, collisions(t), collisions(t) / kRate});
  }
  const double t_fs = 2 * std::pow(10.0, 2.5);
  const double expected = collisions(t_fs) * std::pow(1e4 / t_fs, 1 - 1.83 / 2);
  EXPECT_NEAR(eta.expected_collisions(1e4), expected, 1e-9 * expected);
}

TEST(RunEta, UnknownUntilThereAreTwoTimesAndSamplesStayLogSpaced) {
  RunEta eta(1e6);
  EXPECT_TRUE(std::isnan(eta.seconds_left(10)));
  eta.add({1, 1000, 0.005});
  EXPECT_TRUE(std::isnan(eta.seconds_left(10)));
  // A million samples over three decades, linearly spaced: the estimate
  // stays that of the power law (the last sample is always the newest).
  for (int i = 1; i <= 1000000; ++i) {
    const double t = 1 + i * 1e-3;
    eta.add({t, collisions(t), collisions(t) / kRate});
  }
  EXPECT_NEAR(eta.expected_collisions(1e4), collisions(1e4), 1e-6 * collisions(1e4));
}

}  // namespace
}  // namespace coolgas
