// The run's ETA (simulate/run/run_eta.h) on synthetic runs whose answer is
// known in closed form: C(t) = 1000 t^0.4 collisions (the collision rate of
// a gas with E ~ t^-6/5 falls as sqrt(E) ~ t^-0.6), at 2e5 collisions per
// busy second; and the extrapolation rule on fixed inputs worked by hand.
#include "simulate/run/run_eta.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coolgas {
namespace {

constexpr double kRate = 2e5;
double collisions(double t) { return 1000 * std::pow(t, 0.4); }

// Samples at 20 per decade of t, from 0.01 to 100.
RunEta power_law_run(double L) {
  RunEta eta(L);
  for (int k = -40; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0);
    eta.add({t, collisions(t), collisions(t) / kRate});
  }
  return eta;
}

TEST(RunEta, APowerLawOfCollisionsIsExtrapolatedExactly) {
  const RunEta eta = power_law_run(1e6);  // the finite-size regime (L^(5/2)) far beyond t_end
  EXPECT_NEAR(eta.exponent(1, 100), 0.4, 1e-12);
  EXPECT_NEAR(eta.collision_rate(), kRate, 1e-9 * kRate);
  EXPECT_NEAR(eta.expected_collisions(1e4), collisions(1e4), 1e-9 * collisions(1e4));
  const double left = (collisions(1e4) - collisions(100)) / kRate;
  EXPECT_NEAR(eta.seconds_left(1e4), left, 1e-9 * left);
}

// L = 10: beyond t = 0.5 L^(5/2) = 158.1 the exponent is at most 0.2.
TEST(RunEta, BeyondTheFiniteSizeKneeCollisionsGrowAsTheTailSays) {
  const RunEta eta = power_law_run(10);
  const double knee = 0.5 * std::pow(10.0, 2.5);
  const double expected = collisions(knee) * std::pow(1e4 / knee, 0.2);
  EXPECT_NEAR(eta.expected_collisions(1e4), expected, 1e-9 * expected);
}

// C = 1000 t^0.2 before the knee: the gas has not yet been through the
// clustering regime, where C grows as t^(1 - theta/2) = t^0.4, so the
// extrapolation takes 0.4. Beyond the knee the measured 0.2 is carried on.
TEST(RunEta, BeforeTheKneeCollisionsGrowAtLeastAsInTheClusteringRegime) {
  RunEta ahead(1e6), beyond(2);  // knees at 5e14 and 2.8
  for (int k = -40; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0), c = 1000 * std::pow(t, 0.2);
    ahead.add({t, c, c / kRate});
    beyond.add({t, c, c / kRate});
  }
  const double slow = 1000 * std::pow(1e4, 0.2), clustering = 1000 * std::pow(100.0, 0.2) * std::pow(100.0, 0.4);
  EXPECT_NEAR(ahead.expected_collisions(1e4), clustering, 1e-9 * clustering);
  EXPECT_NEAR(beyond.expected_collisions(1e4), slow, 1e-9 * slow);
}

// Ballistic aggregation: at most N - 1 merges, whatever the extrapolation says.
TEST(RunEta, NoMoreCollisionsThanTheBoundAllows) {
  RunEta eta(1e6, 3e4);
  for (int k = -40; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0);
    eta.add({t, collisions(t), collisions(t) / kRate});
  }
  EXPECT_EQ(eta.expected_collisions(1e4), 3e4);  // the power law would give 39811
  EXPECT_NEAR(eta.seconds_left(1e4), (3e4 - collisions(100)) / kRate, 1e-9);
}

// An exponent 0.6 falling by 0.1 per unit of ln t from t = 10 reaches the
// floor 0.2 at u = ln(t/10) = 4: the integral of a over u in [0, ln 1000] is
// 0.6*4 - 0.1*4^2/2 + 0.2*(ln 1000 - 4).
TEST(RunEta, AFallingExponentFallsToTheFloor) {
  const double u_end = std::log(1000.0);
  EXPECT_NEAR(log_growth(10, 1e4, 0.6, -0.1, 0.2, 1e9, 0.15), 1.6 + 0.2 * (u_end - 4), 1e-12);
  // A rising exponent is not carried on: a stays 0.6.
  EXPECT_NEAR(log_growth(10, 1e4, 0.6, 0.3, 0.2, 1e9, 0.15), 0.6 * u_end, 1e-12);
  // An exponent already below the floor stays where it is.
  EXPECT_NEAR(log_growth(10, 1e4, 0.1, -0.1, 0.2, 1e9, 0.15), 0.1 * u_end, 1e-12);
}

// The same, with the knee at t = 100 (u = ln 10) and a tail cap of 0.3: a is
// 0.6 - 0.1 u up to the knee, then 0.3 until the line falls below it (u = 3),
// then the line down to the floor 0.2 (u = 4), then 0.2.
TEST(RunEta, TheTailCapsTheExponentOnlyBeyondTheKnee) {
  const double u_knee = std::log(10.0), u_end = std::log(1000.0);
  const double by_hand = (0.6 * u_knee - 0.05 * u_knee * u_knee) + 0.3 * (3 - u_knee) + 0.25 + 0.2 * (u_end - 4);
  EXPECT_NEAR(log_growth(10, 1e4, 0.6, -0.1, 0.2, 100, 0.3), by_hand, 1e-12);
  // A cap below the floor holds from the knee on.
  EXPECT_NEAR(log_growth(10, 1e4, 0.6, 0, 0.2, 100, 0.1), 0.6 * u_knee + 0.1 * (u_end - u_knee), 1e-12);
}

// 1e6 collisions per busy second until t = 50, then 2.5e5 (say, another job
// took the core): once the last quarter of the busy time is all at the new
// rate, that is the rate (the mean over the run would be 4e5).
TEST(RunEta, TheRateIsTheRecentOne) {
  RunEta eta(1e6);
  double busy = 0;
  for (int i = 1; i <= 1000; ++i) {
    const double t = 0.1 * i;
    busy += t <= 50 ? 100.0 / 1e6 : 100.0 / 2.5e5;  // 100 collisions per step of t
    eta.add({t, 1000.0 * t, busy});
  }
  EXPECT_NEAR(eta.collision_rate(), 2.5e5, 1e-6 * 2.5e5);
}

TEST(RunEta, UnknownUntilAWholeFitWindowAndSamplesStayLogSpaced) {
  RunEta eta(1e6);
  EXPECT_TRUE(std::isnan(eta.seconds_left(10)));
  eta.add({1, 1000, 0.005});
  eta.add({2, collisions(2), collisions(2) / kRate});
  EXPECT_TRUE(std::isnan(eta.seconds_left(10)));  // t = 1 .. 2 is not yet a factor 3 of t
  // A million samples over three decades, linearly spaced: the estimate
  // stays that of the power law (the last sample is always the newest).
  for (int i = 1; i <= 1000000; ++i) {
    const double t = 2 + i * 1e-3;
    eta.add({t, collisions(t), collisions(t) / kRate});
  }
  EXPECT_NEAR(eta.expected_collisions(1e4), collisions(1e4), 1e-6 * collisions(1e4));
}

}  // namespace
}  // namespace coolgas
