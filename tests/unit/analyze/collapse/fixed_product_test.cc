// The collapse with z theta held fixed (analyze/collapse/fixed_product.h), on
// synthetic runs that obey the paper's Eq. (2) exactly up to run-level noise:
// E = L^{-z theta} f(t/L^z) with f(x) = x^-theta (1 + x)^(theta - eta), times
// exp(a + b u(t) + c w_i) (a run-level offset and tilt, a white part; as in
// resampling_test.cc). Fixed seeds, so every number is reproducible.
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/collapse/ensemble.h"
#include "analyze/collapse/fixed_product.h"
#include "analyze/collapse/optimize.h"
#include "common/error.h"
#include "tests/unit/analyze/collapse/synthetic_runs.h"

namespace coolgas {
namespace {
// Its own namespace: the unity build joins this file with the other collapse tests.
namespace fixed_product_test {

constexpr double kEta = 1.83;

std::vector<SizeEnsemble> ensemble(double theta, double z, int runs_per_size, std::uint64_t seed) {
  return test::synthetic_ensemble(theta, z, kEta, runs_per_size, seed);
}

CollapseSearch start_at(double z0) {
  CollapseSearch s;
  s.z0 = z0;
  s.theta0 = 3 / z0;
  return s;
}

// Data with the paper's z = 5/2, theta = 6/5 (z theta = 3): with the product
// held at 3 the search recovers z within its jackknife error (and 0.05),
// from starts on either side, and theta is 3/z exactly.
TEST(CollapseFixedProduct, RecoversZOfDataWithThatProduct) {
  const auto sizes = ensemble(1.2, 2.5, 4, 11);
  for (double z0 : {2.0, 3.2}) {
    const CollapseFit f = optimize_collapse_fixed_product(sizes, start_at(z0), 3.0);
    EXPECT_EQ(f.kind, BootstrapKind::kRuns);
    EXPECT_EQ(f.replicas, 12);  // one per run
    EXPECT_NEAR(f.z, 2.5, 0.05) << "from z0 = " << z0;
    EXPECT_GT(f.z_err, 0);
    EXPECT_LT(std::abs(f.z - 2.5), 3 * f.z_err);
    EXPECT_EQ(f.theta, 3.0 / f.z);                 // the product is held, not fitted
    EXPECT_NEAR(f.theta * f.z, 3.0, 1e-15 * 3.0);  // to rounding
    EXPECT_NEAR(f.theta_err, 3.0 * f.z_err / (f.z * f.z), 0.01 * f.theta_err);  // first order in z_err
  }
}

// Disks: the 2D mean field has theta = 2d/(d+2) = 1 and z theta = d = 2, so
// z = 2. Data with that scaling, the product held at 2 (--z-theta 2): z = 2
// within its error; held at the 3D value 3, the collapse is clearly worse.
TEST(CollapseFixedProduct, RecoversTheTwoDimensionalMeanFieldZ) {
  const auto sizes = ensemble(1.0, 2.0, 4, 12);
  CollapseSearch s;
  s.z0 = 2.6;
  s.theta0 = 2 / 2.6;
  const CollapseFit f = optimize_collapse_fixed_product(sizes, s, 2.0);
  EXPECT_NEAR(f.z, 2.0, 0.05);
  EXPECT_LT(std::abs(f.z - 2.0), 3 * f.z_err);
  EXPECT_EQ(f.theta, 2.0 / f.z);
  s.bootstrap = 0;
  EXPECT_GT(optimize_collapse_fixed_product(sizes, s, 3.0).quality, 10 * f.quality);
}

// Q at the fixed-product minimum can never be below the free minimum (a
// minimum over a line of the plane), and it is clearly above it when the
// data do not obey the product (z theta = 2.5 in the data, 3 imposed).
TEST(CollapseFixedProduct, QualityIsNeverBetterThanTheFreeFit) {
  CollapseSearch free;
  free.bootstrap = 0;
  CollapseSearch fixed = start_at(2.5);
  fixed.bootstrap = 0;

  const auto obeys = ensemble(1.2, 2.5, 3, 21);
  const CollapseFit f_free = optimize_collapse(obeys, free);
  const CollapseFit f_fixed = optimize_collapse_fixed_product(obeys, fixed, 3.0);
  EXPECT_GE(f_fixed.quality, f_free.quality * (1 - 1e-6));

  const auto other = ensemble(1.0, 2.5, 3, 22);  // z theta = 2.5
  const CollapseFit o_free = optimize_collapse(other, free);
  const CollapseFit o_fixed = optimize_collapse_fixed_product(other, fixed, 3.0);
  EXPECT_NEAR(o_free.z * o_free.theta, 2.5, 0.1);
  EXPECT_GT(o_fixed.quality, 10 * o_free.quality) << o_fixed.quality << " " << o_free.quality;
  // Held at the data's own product, it finds their z again.
  const CollapseFit o_own = optimize_collapse_fixed_product(other, fixed, 2.5);
  EXPECT_NEAR(o_own.z, 2.5, 0.05);
  EXPECT_EQ(o_own.theta, 2.5 / o_own.z);
}

TEST(CollapseFixedProduct, RefusesWhatItCannotDo) {
  Random rng(3);
  std::vector<SizeEnsemble> one_run_each;
  for (double L : {16.0, 32.0}) one_run_each.push_back(SizeEnsemble{L, {test::synthetic_run(L, 1.2, 2.5, kEta, rng)}, {}});
  EXPECT_THROW(optimize_collapse_fixed_product(one_run_each, start_at(2.5), 3.0), InputError);  // no jackknife
  CollapseSearch no_errors = start_at(2.5);
  no_errors.bootstrap = 0;
  EXPECT_NO_THROW(optimize_collapse_fixed_product(one_run_each, no_errors, 3.0));
  EXPECT_THROW(optimize_collapse_fixed_product(one_run_each, no_errors, 0.0), InputError);
  EXPECT_THROW(optimize_collapse_fixed_product(one_run_each, no_errors, std::nan("")), InputError);
  EXPECT_THROW(optimize_collapse_fixed_product({one_run_each[0]}, no_errors, 3.0), InputError);
}

}  // namespace fixed_product_test
}  // namespace
}  // namespace coolgas
