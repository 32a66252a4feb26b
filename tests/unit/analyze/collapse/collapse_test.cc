// Finite-size scaling (collapse_*.h) on synthetic curves built from the
// paper's Eq. (2), E(t, L) = L^{-z theta} f(t / L^z), with the scaling
// function f(x) = x^-theta (1 + x)^(theta - eta): x^-theta for x << 1 and
// x^-eta for x >> 1, with the paper's theta = 6/5, z = 5/2, eta = 1.83
// (Pathak, Jabeen, Das, Rajesh 2014, Fig. 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analyze/collapse/curves.h"
#include "analyze/collapse/optimize.h"
#include "analyze/collapse/quality.h"
#include "analyze/collapse/tail.h"
#include "analyze/collapse/table.h"
#include "common/error.h"
#include "tests/support/fit_test_data.h"

namespace coolgas {
namespace {

constexpr double kTheta = 1.2, kZ = 2.5, kEta = 1.83;

double scaling_function(double x) { return std::pow(x, -kTheta) * std::pow(1 + x, kTheta - kEta); }

// The E(t) table of size L as coolgas-energy would write it: t from 1 to 1e7,
// 20 rows per decade, multiplicative noise sigma (seeded by L) and E_err = sigma E.
Table synthetic_table(double L, double sigma) {
  const auto model = [L](double t) { return std::pow(L, -kZ * kTheta) * scaling_function(t / std::pow(L, kZ)); };
  const FitData d = test::noisy_samples(model, 1, 1e7, 20, sigma, static_cast<unsigned long>(L));
  Table t;
  t.source = format_number(L);
  t.source += ".tsv";  // (one append at a time: GCC 12 warns falsely on "L" + std::string)
  t.provenance = {{"tool", "coolgas-energy"}, {"L", format_number(L)}};
  t.columns = {"t", "E", "E_err"};
  for (std::size_t i = 0; i < d.t.size(); ++i) t.rows.push_back({d.t[i], d.E[i], sigma * d.E[i]});
  return t;
}

std::vector<ScalingCurve> synthetic_curves(double sigma) {
  std::vector<ScalingCurve> c;
  for (double L : {16, 24, 32, 48, 64}) c.push_back(make_scaling_curve(synthetic_table(L, sigma), {}, {}));
  return c;
}

TEST(CollapseQuality, IsSmallestAtTheTrueExponents) {
  const auto curves = synthetic_curves(0);
  const double q = collapse_quality(curves, kTheta, kZ, 0.5);
  EXPECT_LT(q, 1e-6);  // only the linear interpolation between rows 1/20 decade apart
  for (auto [dtheta, dz] : {std::pair{0.03, 0.0}, {-0.03, 0.0}, {0.0, 0.05}, {0.0, -0.05}})
    EXPECT_GT(collapse_quality(curves, kTheta + dtheta, kZ + dz, 0.5), 100 * q) << dtheta << " " << dz;
}

TEST(CollapseQuality, PairsWithoutOverlapArePenalised) {
  const auto curves = synthetic_curves(0);
  // z = 80 moves each curve by at least 80 log10(4/3) = 10 decades of x from
  // the next, more than the 7 decades each spans: no pair overlaps.
  EXPECT_EQ(collapse_quality(curves, kTheta, 80, 0.5), kNoOverlapPenalty);
}

TEST(CollapseOptimize, RecoversThetaAndZFromNoisyCurves) {
  CollapseSearch s;
  s.theta0 = 1.0;  // start away from the answer
  s.z0 = 2.0;
  s.bootstrap = 40;
  s.seed = 3;
  // 1 % noise: at 2 % the noise roughens Q's long theta-z valley and the
  // bootstrap errors become erratic (see analyze/collapse/optimize.h).
  const CollapseFit f = optimize_collapse(synthetic_curves(0.01), s);
  EXPECT_GT(f.theta_err, 0);
  EXPECT_LT(f.theta_err, 0.02);
  EXPECT_LT(f.z_err, 0.02);
  EXPECT_EQ(f.kind, BootstrapKind::kErrors);
  EXPECT_NEAR(f.theta, kTheta, std::min(0.02, 3 * f.theta_err));
  EXPECT_NEAR(f.z, kZ, std::min(0.02, 3 * f.z_err));
}

TEST(CollapseTail, RecoversEtaOfTheScalingFunction) {
  // The local slope of f is theta + (eta - theta) x/(1+x): within 0.007 of eta for x >= 100.
  const auto eta = fit_tail_exponent(synthetic_curves(0.02), kTheta, kZ, {100.0, 1e4});
  ASSERT_TRUE(eta);
  EXPECT_NEAR(eta->theta, kEta, 0.01);
  EXPECT_LT(eta->theta_err, 0.01);
}

TEST(CollapseTail, WindowBeyondTheDataGivesNoEta) {
  // The curves end at t = 1e7; at z = 6 even the smallest box has L^z =
  // 16^6 = 1.7e7, so every scaled point lies at x < 1, none in 100:1e4.
  EXPECT_FALSE(fit_tail_exponent(synthetic_curves(0.02), kTheta, 6.0, {100.0, 1e4}));
}

TEST(CollapseCurves, TableWithoutLIsRefused) {
  Table t = synthetic_table(16, 0);
  t.provenance = {{"tool", "coolgas-fit"}};
  EXPECT_THROW(make_scaling_curve(t, {}, {}), InputError);
}

// A 1D table (its '# dimension: 1' line) beside 3D ones is refused with one
// line naming both tables and their dimensions; 1D tables alone collapse,
// and the result says its dimension.
TEST(CollapseTables, OneDimensionalTablesAreNotMixedWithOthers) {
  std::vector<Table> tables{synthetic_table(16, 0), synthetic_table(32, 0)};
  tables[1].provenance.emplace_back("dimension", "1");
  try {
    collapse_tables(tables, CollapseOptions{});
    FAIL() << "a 1D and a 3D table were collapsed together";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("16.tsv is 3D, 32.tsv is 1D"), std::string::npos) << e.what();
  }
  tables[0].provenance.emplace_back("dimension", "1");
  const CollapseResult r = collapse_tables(tables, CollapseOptions{});
  EXPECT_NE(std::find(r.provenance.begin(), r.provenance.end(), std::pair<std::string, std::string>{"dimension", "1"}),
            r.provenance.end());
}

}  // namespace
}  // namespace coolgas
