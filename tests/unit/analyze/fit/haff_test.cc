// Haff fit (analyze/fit/haff.h) and the local slope (analyze/fit/local_slope.h) on Haff's law
// E0/(1 + t/t0)^2 with t0 = 6/(1 - r^2) (shared/oracles: Haff's law in this
// project's units; r = 0.9 gives t0 = 31.58).
#include "analyze/fit/haff.h"

#include <gtest/gtest.h>

#include <cmath>

#include "analyze/fit/local_slope.h"
#include "common/error.h"
#include "tests/support/fit_test_data.h"

namespace coolgas {
namespace {

const double kT0 = 6 / (1 - 0.9 * 0.9);

double haff(double t) { return 1.5 / std::pow(1 + t / kT0, 2); }

TEST(HaffFit, ExactHaffLawIsRecoveredExactly) {
  const HaffFit f = fit_haff(test::noisy_samples(haff, 0.1, 1e4, 10, 0, 1));
  EXPECT_NEAR(f.E0, 1.5, 1e-9);
  EXPECT_NEAR(f.t0 / kT0, 1, 1e-9);
}

TEST(HaffFit, NoisyDataGiveE0AndT0WithinTheirErrors) {
  const HaffFit f = fit_haff(test::noisy_samples(haff, 0.1, 1e4, 20, 0.02, 7));
  ASSERT_TRUE(f.weighted);
  EXPECT_LT(f.t0_err / kT0, 0.01);
  EXPECT_NEAR(f.t0, kT0, 3 * f.t0_err);
  EXPECT_NEAR(f.E0, 1.5, 3 * f.E0_err);
  EXPECT_NEAR(f.chi2_dof, 1.0, 0.4);
}

TEST(LocalSlope, IsTheExponentOfAPowerLawEverywhere) {
  const auto s = local_slope(test::noisy_samples([](double t) { return 2 * std::pow(t, -1.83); }, 1, 1e4, 10, 0, 1), 0.25);
  ASSERT_GT(s.size(), 30u);
  for (const auto& p : s) EXPECT_NEAR(p.slope, 1.83, 1e-10) << p.t;
}

TEST(LocalSlope, FollowsHaffsLaw) {
  // -d ln E / d ln t = 2 u / (1 + u), u = t/t0: 1 at t = t0, tending to 2.
  // A narrow window (0.05 decades) keeps the smoothing bias below 1e-3.
  const auto s = local_slope(test::noisy_samples(haff, kT0 / 100, kT0 * 1000, 40, 0, 1), 0.05);
  for (const auto& p : s) {
    const double u = p.t / kT0;
    EXPECT_NEAR(p.slope, 2 * u / (1 + u), 1e-3) << p.t;
  }
}

TEST(LocalSlope, TooNarrowAWindowIsAnInputError) {
  EXPECT_THROW(local_slope(test::noisy_samples(haff, 1, 100, 2, 0, 1), 0.1), InputError);
}

}  // namespace
}  // namespace coolgas
