// The collapse weighted by the scatter of each size's runs
// (analyze/collapse/seed_weights.h): the variance it estimates, and on
// synthetic ensembles whose late times wander as small boxes do (a random
// walk of ln E in ln x for x > 1, the same for every L, so the runs of a
// size disagree more the later it is) that it finds theta and z closer to
// the truth than the unweighted collapse, with a jackknife error (weights
// estimated again in every replica) that still covers the truth at about its
// stated rate.
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/collapse/ensemble.h"
#include "analyze/collapse/optimize.h"
#include "analyze/collapse/seed_weights.h"
#include "common/error.h"
#include "common/random.h"

namespace coolgas {
namespace {

constexpr double kWalkTheta = 1.2, kWalkZ = 2.5, kWalkEta = 1.83;

ScalingCurve curve_from(double L, const std::vector<double>& t, const std::vector<double>& ln_E) {
  ScalingCurve c;
  c.source = "synthetic";
  c.L = L;
  c.ln_L = std::log(L);
  c.t = t;
  c.ln_E = ln_E;
  for (std::size_t i = 0; i < t.size(); ++i) {
    c.ln_t.push_back(std::log(t[i]));
    c.E.push_back(std::exp(ln_E[i]));
  }
  return c;
}

// The paper's Eq. (2) with f(x) = x^-theta (1 + x)^(theta - eta), a run-level
// offset, a 0.5 % white part and, past x = 1, a random walk of ln E with 0.3
// per unit of ln x (at x = 100 the runs spread by about a factor 2).
ScalingCurve wandering_run(double L, Random& rng) {
  std::vector<double> t, ln_E;
  const double offset = 0.03 * rng.normal();
  double walk = 0, last_ln_x = 0;
  for (int k = 0; k <= 60; ++k) {  // t = 1 .. 1e6, 10 per decade
    const double tk = std::pow(10.0, k / 10.0), ln_x = std::log(tk) - kWalkZ * std::log(L);
    if (ln_x > 0) walk += 0.3 * std::sqrt(ln_x - std::max(last_ln_x, 0.0)) * rng.normal();
    last_ln_x = ln_x;
    t.push_back(tk);
    ln_E.push_back(-kWalkZ * kWalkTheta * std::log(L) - kWalkTheta * ln_x + (kWalkTheta - kWalkEta) * std::log1p(std::exp(ln_x)) +
                   offset + walk + 0.005 * rng.normal());
  }
  return curve_from(L, t, ln_E);
}

std::vector<SizeEnsemble> wandering_ensemble(int runs, std::uint64_t seed, bool weigh) {
  Random rng(seed);
  std::vector<SizeEnsemble> sizes;
  for (double L : {16.0, 32.0, 64.0}) {
    SizeEnsemble s{L, {}, {}};
    for (int r = 0; r < runs; ++r) s.runs.push_back(wandering_run(L, rng));
    if (weigh) estimate_seed_scatter(s);
    sizes.push_back(s);
  }
  return sizes;
}

TEST(SeedWeights, VarianceOfOneRunIsTheSpreadOfLnEOverTheMeanAndFallsWithRuns) {
  // Two runs a constant factor 1.2 apart: E_1 = E, E_2 = 1.2 E at every time.
  std::vector<double> t{1, 2, 4, 8, 16, 32, 64, 128}, a, b;
  for (double tk : t) {
    a.push_back(-std::log(tk));
    b.push_back(-std::log(tk) + std::log(1.2));
  }
  SizeEnsemble e{10, {curve_from(10, t, a), curve_from(10, t, b)}, {}};
  estimate_seed_scatter(e);
  // Sample variance of E over its mean squared (delta method): (E_1 - E_2)^2 / 2 / ((E_1 + E_2) / 2)^2.
  const double expected = 0.2 * 0.2 / 2 / (1.1 * 1.1);
  ASSERT_EQ(e.scatter.var.size(), t.size());
  for (double v : e.scatter.var) EXPECT_NEAR(v, expected, 1e-12);
  const auto one = mean_ln_E_variance(e, {std::log(3.0)}, 1), two = mean_ln_E_variance(e, {std::log(3.0)}, 2);
  EXPECT_NEAR(one[0], expected, 1e-12);
  EXPECT_NEAR(two[0], expected / 2, 1e-12);
  EXPECT_EQ(ensemble_mean(e).ln_E_var.size(), t.size());  // the mean of both carries its weights
}

TEST(SeedWeights, IdenticalRunsAreKnownToTheFloorAndOneRunIsRefused) {
  std::vector<double> t{1, 10, 100}, ln_E{0, -1, -2};
  SizeEnsemble twins{10, {curve_from(10, t, ln_E), curve_from(10, t, ln_E)}, {}};
  estimate_seed_scatter(twins);
  for (double v : twins.scatter.var) EXPECT_DOUBLE_EQ(v, kScatterFloor * kScatterFloor);
  SizeEnsemble single{34, {curve_from(34, t, ln_E)}, {}};
  try {
    estimate_seed_scatter(single);
    FAIL() << "one run was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("L = 34 has 1"), std::string::npos) << e.what();
  }
}

// Over 40 ensembles of 4 runs per size: the weighted collapse's z is closer to
// the truth (root mean square) than the unweighted one's, and its one standard
// error covers the truth in 50-86 % of them (68 % expected; binomial sd 7 %).
// Measured over 60 ensembles: rms error of z 0.42 unweighted, 0.072 weighted;
// coverage of theta and z 63 % and 75 % with 4 runs, 68 % and 85 % with 3,
// 65 % and 68 % with 8, but 42 % and 40 % with 2 runs per size, whose
// replicas cannot estimate their weights again (seed_weights.h).
TEST(SeedWeights, WeightedCollapseIsCloserToTheTruthAndItsErrorCoversIt) {
  const int trials = 40;
  double ss_plain = 0, ss_weighted = 0;
  int theta_in = 0, z_in = 0;
  CollapseSearch s;
  for (std::uint64_t seed = 1; seed <= trials; ++seed) {
    const CollapseFit plain = optimize_collapse(wandering_ensemble(4, seed, false), s);
    const CollapseFit w = optimize_collapse(wandering_ensemble(4, seed, true), s);
    ASSERT_EQ(w.kind, BootstrapKind::kRuns);
    ss_plain += (plain.z - kWalkZ) * (plain.z - kWalkZ);
    ss_weighted += (w.z - kWalkZ) * (w.z - kWalkZ);
    theta_in += std::abs(w.theta - kWalkTheta) <= w.theta_err;
    z_in += std::abs(w.z - kWalkZ) <= w.z_err;
  }
  EXPECT_LT(ss_weighted, 0.5 * ss_plain);
  EXPECT_GE(theta_in, 0.50 * trials);
  EXPECT_LE(theta_in, 0.86 * trials);
  EXPECT_GE(z_in, 0.50 * trials);
  EXPECT_LE(z_in, 0.86 * trials);
}

}  // namespace
}  // namespace coolgas
