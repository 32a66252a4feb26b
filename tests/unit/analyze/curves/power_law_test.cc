// Power-law fit (analyze/curves/power_law.h): exact data give the exact exponent; noisy
// data with known errors give the exponent within its standard error and
// chi^2 per degree of freedom near 1.
#include "analyze/curves/power_law.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"
#include "tests/support/fit_test_data.h"

namespace coolgas {
namespace {

TEST(PowerLawFit, ExactPowerLawIsRecoveredExactly) {
  const FitData d = test::noisy_samples([](double t) { return 3.0 * std::pow(t, -1.2); }, 1, 1e4, 10, 0, 1);
  const PowerLawFit f = fit_power_law(d);
  EXPECT_NEAR(f.theta, 1.2, 1e-12);
  EXPECT_NEAR(f.A, 3.0, 1e-11);
  EXPECT_FALSE(f.weighted);
}

TEST(PowerLawFit, NoisyDataGiveTheExponentWithinItsError) {
  // The paper's theta = 6/5 (Eq. 2 and Fig. 1), 5 decades, 2 % noise.
  const FitData d = test::noisy_samples([](double t) { return 3.0 * std::pow(t, -1.2); }, 1, 1e5, 20, 0.02, 42);
  const PowerLawFit f = fit_power_law(d);
  ASSERT_TRUE(f.weighted);
  EXPECT_GT(f.theta_err, 0);
  EXPECT_LT(f.theta_err, 0.005);  // sigma/sqrt(n)/spread of ln t: about 0.0011 here
  EXPECT_NEAR(f.theta, 1.2, 3 * f.theta_err);
  EXPECT_NEAR(f.A, 3.0, 3 * f.A_err);
  EXPECT_NEAR(f.chi2_dof, 1.0, 0.4);  // 99 degrees of freedom: sd of chi2/dof is 0.14
}

TEST(PowerLawFit, PointsOutsideTheLogLogPlaneAreRefused) {
  FitData d{{0, 1, 2}, {1, 0.5, 0.25}, {}};
  EXPECT_THROW(fit_power_law(d), InputError);
}

}  // namespace
}  // namespace coolgas
