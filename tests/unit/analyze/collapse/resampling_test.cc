// The errors of theta and z from resampling whole runs (analyze/collapse/
// optimize.h, kRuns), on synthetic ensembles whose runs are correlated in
// time as real ones are: each run of size L is the paper's Eq. (2),
// E = L^{-z theta} f(t/L^z) with f(x) = x^-theta (1 + x)^(theta - eta),
// times exp(a + b u(t) + c w_i): a run-level offset a and tilt b (u runs from
// -1 to 1 over the run's decades in log t) and a small white part c. A
// standard error should (i) fall as 1/sqrt(runs) and (ii) cover the true
// value about 68 % of the time. The parametric bootstrap over the errors of
// the mean treats the times as independent and fails (ii).
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/collapse/ensemble.h"
#include "analyze/collapse/optimize.h"
#include "tests/unit/analyze/collapse/synthetic_runs.h"

namespace coolgas {
namespace {

constexpr double kTrueTheta = 1.2, kTrueZ = 2.5, kTrueEta = 1.83;

std::vector<SizeEnsemble> synthetic_ensemble(int runs_per_size, std::uint64_t seed) {
  return test::synthetic_ensemble(kTrueTheta, kTrueZ, kTrueEta, runs_per_size, seed);
}

CollapseFit fit(const std::vector<SizeEnsemble>& sizes) {
  CollapseSearch s;
  s.bootstrap = 40;  // used only by the bootstrap kinds
  return optimize_collapse(sizes, s);
}

TEST(CollapseResampling, MeanOfRunsAveragesEAtTheirCommonTimes) {
  Random rng(1);
  SizeEnsemble e{16, {test::synthetic_run(16, kTrueTheta, kTrueZ, kTrueEta, rng), test::synthetic_run(16, kTrueTheta, kTrueZ, kTrueEta, rng)}, {}};
  e.runs[1].t.erase(e.runs[1].t.begin());  // the second run lacks the first time
  e.runs[1].E.erase(e.runs[1].E.begin());
  e.runs[1].ln_t.erase(e.runs[1].ln_t.begin());
  e.runs[1].ln_E.erase(e.runs[1].ln_E.begin());
  const ScalingCurve m = ensemble_mean(e);
  ASSERT_EQ(m.t.size(), e.runs[1].t.size());
  EXPECT_EQ(m.t[0], e.runs[1].t[0]);
  const double a = e.runs[0].E[1], b = e.runs[1].E[0];
  EXPECT_DOUBLE_EQ(m.E[0], (a + b) / 2);
  EXPECT_DOUBLE_EQ(m.ln_E_err[0], std::abs(a - b) / 2 / m.E[0]);  // s / sqrt(2) with s = |a - b| / sqrt(2)
}

TEST(CollapseResampling, UsesTheJackknifeOverRunsWhenEverySizeHasSeveralRuns) {
  const CollapseFit f = fit(synthetic_ensemble(4, 7));
  EXPECT_EQ(f.kind, BootstrapKind::kRuns);
  EXPECT_EQ(f.replicas, 12);  // one per run
  EXPECT_GT(f.theta_err, 0);
  EXPECT_GT(f.z_err, 0);
}

// (i) Four times the runs, half the error: mean error over 8 ensembles each.
TEST(CollapseResampling, ErrorFallsAsOneOverSqrtRuns) {
  double few = 0, many = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    few += fit(synthetic_ensemble(4, seed)).theta_err;
    many += fit(synthetic_ensemble(16, 100 + seed)).theta_err;
  }
  EXPECT_NEAR(many / few, 0.5, 0.12);
}

// (ii) |theta - 6/5| <= theta_err in about 68 % of 40 ensembles (binomial
// standard deviation 7 %), and likewise for z and for the product z theta
// (whose error comes from the same replicas, keeping their correlation).
TEST(CollapseResampling, OneStandardErrorCoversTheTruthAtItsStatedRate) {
  int theta_in = 0, z_in = 0, product_in = 0, bootstrap_in = 0;
  const int trials = 40;
  for (std::uint64_t seed = 1; seed <= trials; ++seed) {
    const auto sizes = synthetic_ensemble(5, 1000 + seed);
    const CollapseFit f = fit(sizes);
    theta_in += std::abs(f.theta - kTrueTheta) <= f.theta_err;
    z_in += std::abs(f.z - kTrueZ) <= f.z_err;
    product_in += std::abs(f.z * f.theta - kTrueZ * kTrueTheta) <= f.z_theta_err;
    CollapseSearch s;
    s.bootstrap = 40;
    const CollapseFit p = optimize_collapse(mean_curves(sizes), s);  // one mean curve per size
    ASSERT_EQ(p.kind, BootstrapKind::kErrors);
    bootstrap_in += std::abs(p.theta - kTrueTheta) <= p.theta_err;
  }
  EXPECT_GE(theta_in, 0.50 * trials);
  EXPECT_LE(theta_in, 0.86 * trials);
  EXPECT_GE(z_in, 0.50 * trials);
  EXPECT_LE(z_in, 0.86 * trials);
  EXPECT_GE(product_in, 0.50 * trials);
  EXPECT_LE(product_in, 0.86 * trials);
  EXPECT_LT(bootstrap_in, 0.40 * trials);  // the point bootstrap's error is far too small here
}

}  // namespace
}  // namespace coolgas
