// The run's ETA (simulate/run/run_eta.h) on synthetic runs whose answer is
// known in closed form, at 2e5 collisions per busy second, and the
// extrapolation rule on fixed inputs worked by hand. Haff's law: with
// E ~ (1 + t/tau)^-2 and a collision rate ~ sqrt(E), C ~ ln(1 + x), x = t/tau,
// whose local exponent is h(x) = x / ((1 + x) ln(1 + x)) and whose growth
// from x0 to x1 is ln(ln(1 + x1) / ln(1 + x0)).
#include "simulate/run/models.h"
#include "simulate/run/run_eta.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace coolgas {
namespace {

constexpr double kRate = 2e5;
double h(double x) { return x / ((1 + x) * std::log1p(x)); }
double haff(double x0, double x1) { return std::log(std::log1p(x1) / std::log1p(x0)); }

// Samples at 20 per decade of t, from 0.01 to 100, of C = 1000 t^p.
RunEta power_law_run(RunEta eta, double p) {
  for (int k = -40; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0), c = 1000 * std::pow(t, p);
    eta.add({t, c, c / kRate});
  }
  return eta;
}
RunEta power_law_run(double L, double p) { return power_law_run(RunEta(L), p); }

RunParameters gas(const std::string& model, double L, double phi, double r0, double delta) {
  RunParameters p;
  p.model = model, p.N = 1000, p.L = L, p.phi = phi, p.collision["r0"] = r0, p.collision["delta"] = delta;
  return p;
}

// An elastic gas: C = 1000 t (the collision rate does not change).
TEST(RunEta, AGasThatDoesNotCoolIsExtrapolatedExactly) {
  const RunEta eta = power_law_run(INFINITY, 1);
  EXPECT_NEAR(eta.exponent(1, 100), 1, 1e-12);
  EXPECT_NEAR(eta.collision_rate(), kRate, 1e-9 * kRate);
  EXPECT_NEAR(eta.expected_collisions(1e4), 1e7, 1e-9 * 1e7);
  const double left = (1e7 - 1e5) / kRate;
  EXPECT_NEAR(eta.seconds_left(1e4), left, 1e-9 * left);
}

// From t = 10 (x0 = 2, so tau = 5) to 1e4 (x1 = 2000), without floor, knee or tail.
TEST(RunEta, TheExponentFallsAsUnderHaffsLaw) {
  EXPECT_NEAR(log_growth(10, 1e4, h(2), 0, INFINITY, 1, 0), haff(2, 2000), 1e-12);
}

// The same with a clustering floor h(20): Haff's law until x = 20, then the
// floor over ln(2000 / 20). An exponent already below the floor is raised to it.
TEST(RunEta, BeforeTheKneeTheExponentIsAtLeastTheClusteringOne) {
  const double floor = h(20);
  EXPECT_NEAR(log_growth(10, 1e4, h(2), floor, INFINITY, 1, 0), haff(2, 20) + floor * std::log(100.0), 1e-12);
  EXPECT_NEAR(log_growth(10, 1e4, 0.3, 0.5, INFINITY, 1, 0), 0.5 * std::log(1000.0), 1e-12);
}

// The knee at t = 100 (x = 20) and a constant tail h(200): Haff's law to the
// knee, the tail while Haff's exponent is above it (x = 20 .. 200), then
// Haff's law. Beyond the knee the integral is taken by midpoints, 64 per unit
// of ln t: an error of order 1e-5 here (the kink where the two meet).
TEST(RunEta, BeyondTheKneeTheTailCapsTheExponent) {
  const double tail = h(200);
  EXPECT_NEAR(log_growth(10, 1e4, h(2), 0, 100, tail, 0), haff(2, 20) + tail * std::log(10.0) + haff(200, 2000),
              1e-4);
}

// A falling tail caps a gas that does not cool (a = 1): beyond the knee at
// t = 100 the exponent is 0.3 (t/100)^-0.5, whose integral over ln t from
// 100 to 1e4 is (0.3 / 0.5) (1 - 100^-0.5) = 0.54. A run already beyond the
// knee (t = 1e3) gets the tail as it is by then: 0.6 (10^-0.5 - 100^-0.5).
TEST(RunEta, BeyondTheKneeTheTailFallsAsAPowerOfTime) {
  EXPECT_NEAR(log_growth(10, 1e4, 1, 0, 100, 0.3, 0.5), std::log(10.0) + 0.54, 1e-5);
  EXPECT_NEAR(log_growth(1e3, 1e4, 1, 0, 100, 0.3, 0.5), 0.6 * (std::pow(10.0, -0.5) - 0.1), 1e-5);
}

// C = 1000 t^0.2, below the clustering regime's 0.5, before the knee: the
// extrapolation takes 0.5. Beyond it (L = 2, knee at t = 2.8) Haff's law
// from the measured 0.2 on, below the tail.
TEST(RunEta, ASlowGrowthBeforeTheKneeIsRaisedToTheClusteringRegimes) {
  const double now = 1000 * std::pow(100.0, 0.2);
  EXPECT_NEAR(power_law_run(1e6, 0.2).expected_collisions(1e4), now * std::pow(100.0, 0.5), 1e-9 * now * 10);
  const RunEta beyond = power_law_run(2, 0.2);
  EXPECT_LT(beyond.expected_collisions(1e4), now * std::pow(100.0, 0.2));
  EXPECT_GT(beyond.expected_collisions(1e4), now);
}

// A run's own rule: C = 1000 t^0.2 before the knee is carried on at the
// gas's floor (the inelastic gas's own, clustering_floor(); the generic
// cooling gas's for a viscoelastic one); an elastic gas is extrapolated at
// its own exponent whatever its box (no knee); aggregation counts its
// aggregates (AggregationFollowsTheMeanFieldLaw). How well the floors
// serve real runs: run_eta_replay_test.cc.
TEST(RunEta, EachModelGetsItsOwnRule) {
  const double now = 1000 * std::pow(100.0, 0.2), tol = 1e-9 * now * 100;
  EXPECT_NEAR(power_law_run(run_eta_for(gas("inelastic", 1e6, 0.208, 0.1, 1e-4), Geometry(3)), 0.2).expected_collisions(1e4),
              now * std::pow(100.0, clustering_floor(0.208, 0.1, 1e-4)), tol);
  RunParameters visco = gas("viscoelastic", 1e6, 0.208, 1, 0);
  visco.collision.clear();
  EXPECT_NEAR(power_law_run(run_eta_for(visco, Geometry(3)), 0.2).expected_collisions(1e4),
              power_law_run(eta_of_cooling_gas(visco), 0.2).expected_collisions(1e4), tol);
  RunParameters elastic = gas("elastic", 2, 0.208, 1, 0);
  EXPECT_NEAR(power_law_run(run_eta_for(elastic, Geometry(3)), 1).expected_collisions(1e4), 1e7, 1e-9 * 1e7);
}

// A driven gas (simulate/engine/driving.h) is extrapolated at its own rule
// whatever its model: one that relaxed into a steady state at rate nu,
// C = C0 + nu t, whose local exponent is still below 1 (0.9 here at
// t = 100), is carried on in proportion to t (the cooling gas's rule would
// have it fall as under Haff's law, the inelastic gas's to its clustering
// floor: far too few); one that heats (C = 1000 t^(4/3), an elastic gas
// heating as T ~ t^(2/3)) keeps its exponent, also in a small box.
TEST(RunEta, ADrivenGasGrowsAtLeastInProportionToTime) {
  RunParameters driven = gas("inelastic", 20, 0.05, 0.5, 0);
  driven.driving_power = 1.0;
  RunEta steady = run_eta_for(driven, Geometry(3));
  for (int k = -40; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0), c = 1e4 + 1000 * t;
    steady.add({t, c, c / kRate});
  }
  const double now = 1e4 + 1e5;
  EXPECT_NEAR(steady.expected_collisions(1e4), now * 100, 1e-9 * now * 100);  // 1.1e7; the exact 1.0e7 is 10 % below
  EXPECT_GT(power_law_run(run_eta_for(driven, Geometry(3)), 1).expected_collisions(1e4), 0.99e7);
  driven.model = "elastic";
  const double heated = 1000 * std::pow(100.0, 4.0 / 3.0) * std::pow(100.0, 4.0 / 3.0);
  EXPECT_NEAR(power_law_run(run_eta_for(driven, Geometry(3)), 4.0 / 3.0).expected_collisions(1e4), heated,
              1e-9 * heated);
}

// Ballistic aggregation of N = 1e6, sampled 20 times a decade from t = 1 to
// 100. The aggregates left, n = N - C, carried on along the mean field's
// n ~ (1 + t/tau)^-6/5 through their local exponent beta now:
// - n = N t^-1.5, steeper than the mean field, keeps its power law: from
//   n(100) = 1000 to n(1e3) = 1000 * 10^-1.5 = 31.6, and never below one
//   aggregate (N - 1 merges by t = 1e5);
// - n = N (1 + t)^-6/5 (tau = 1) is the mean field itself: the merges by
//   t = 1e4 are those of the law to within 1e-4 of n(100) (3.5e-5: its
//   local exponent is fitted over t = 33 .. 100, not taken at 100);
// - n = 1e6 - 1e3 t, linear in t (n barely falls yet: beta = 0.066 over
//   t = 33 .. 100), is still expected to fall along the mean field: by
//   t = 1e4 to 10.7 % of n(100) (x = t/tau = beta / (6/5 - beta) = 0.058),
//   where a power law at beta would keep 74 %.
RunEta aggregation_run(double (*aggregates)(double t)) {
  RunParameters p = gas("aggregation", 1e6, 0.208, 1, 0);
  p.N = 1000000;
  RunEta eta = run_eta_for(p, Geometry(3));
  for (int k = 0; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0), c = 1e6 - aggregates(t);
    eta.add({t, c, c / kRate});
  }
  return eta;
}

TEST(RunEta, AggregationFollowsTheMeanFieldLaw) {
  const RunEta steep = aggregation_run([](double t) { return 1e6 * std::pow(t, -1.5); });
  EXPECT_NEAR(steep.expected_collisions(1e3), 1e6 - 1000 * std::pow(10.0, -1.5), 1e-6);
  EXPECT_EQ(steep.expected_collisions(1e5), 1e6 - 1);
  EXPECT_NEAR(steep.frame_size(1e3), 1000 * std::pow(10.0, -1.5), 1e-6);
  EXPECT_NEAR(steep.frame_size(100), 1000, 1e-6);
  const auto mean_field = [](double t) { return 1e6 * std::pow(1 + t, -1.2); };
  const RunEta law = aggregation_run(mean_field);
  EXPECT_NEAR(law.expected_collisions(1e4), 1e6 - mean_field(1e4), 1e-4 * mean_field(100));
  const RunEta slow = aggregation_run([](double t) { return 1e6 - 1e3 * t; });
  EXPECT_NEAR(slow.frame_size(1e4) / 9e5, 0.107, 0.001);
}

// A bound on the collisions holds whatever the extrapolation says.
// C = 1000 t^0.5, at the clustering floor, would reach 1e5 at t = 1e4.
TEST(RunEta, NoMoreCollisionsThanTheBoundAllows) {
  RunEta eta(1e6, 3e4);
  for (int k = -40; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0), c = 1000 * std::sqrt(t);
    eta.add({t, c, c / kRate});
  }
  EXPECT_EQ(eta.expected_collisions(1e4), 3e4);
  EXPECT_NEAR(eta.seconds_left(1e4), (3e4 - 1e4) / kRate, 1e-9);
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

// Aggregation's engine rebuilds its grid each time the aggregates fall by
// a factor 4 (AggregationEngine::kCellsPerAggregateLimit), at a search per
// aggregate. BA of N = 1e6 with n = N (1 + t)^-6/5, sampled 20 times a decade
// up to t = 10^0.5 = 3.16, merging at 2e5 per busy second, with a rebuild
// of 1 s once n < N/4 (t = 4^(5/6) - 1 = 2.17). The rate spans the last
// factor 4 of n: from the newest sample with n >= 4 n(3.16), i.e.
// (1 + t) <= 4.16 / 4^(5/6) = 1.31, t = 10^(-11/20) = 0.28. The last
// quarter of the busy time alone (a gas's window) would hold little but
// the rebuild.
TEST(RunEta, AggregationsRateSpansAGridPeriod) {
  const auto merges = [](double t) { return 1e6 - 1e6 * std::pow(1 + t, -1.2); };
  const auto busy = [&](double t) { return merges(t) / kRate + (merges(t) > 7.5e5 ? 1.0 : 0.0); };
  RunParameters p = gas("aggregation", 1e6, 0.208, 1, 0);
  p.N = 1000000;
  RunEta ba = run_eta_for(p, Geometry(3)), gas_like(INFINITY);
  for (int k = -40; k <= 10; ++k) {
    const double t = std::pow(10.0, k / 20.0);
    ba.add({t, merges(t), busy(t)});
    gas_like.add({t, merges(t), busy(t)});
  }
  const double now = std::pow(10.0, 0.5), from = std::pow(10.0, -11 / 20.0);
  const double period = (merges(now) - merges(from)) / (busy(now) - busy(from));
  EXPECT_NEAR(ba.collision_rate(), period, 1e-9 * period);
  EXPECT_GT(period, 0.7 * kRate);
  EXPECT_LT(gas_like.collision_rate(), 0.5 * period);
}

// The inelastic gas counts its work in events, at 2e5 per busy second:
// C = 1000 t^0.2 is raised to its floor 0.6 before the knee; of the other
// events (crossings), 3000 t^0.7 falls as under Haff's law to the floor
// 1 - theta/2 = 0.4 (theta = 6/5), while 3000 t^0.1, already below it, keeps
// its exponent. From t = 100 to 1e4. Without event counts (NaN) the same run
// is counted in collisions, at their own rate.
RunEta inelastic_run(double crossing_exponent, bool events_known) {
  RunEta eta = run_eta_for(gas("inelastic", 1e6, 0.208, 0.1, 1e-4), Geometry(3));
  for (int k = -40; k <= 40; ++k) {
    const double t = std::pow(10.0, k / 20.0), c = 1000 * std::pow(t, 0.2);
    const double x = 3000 * std::pow(t, crossing_exponent);
    eta.add({t, c, (c + x) / kRate, events_known ? c + x : NAN});
  }
  return eta;
}

TEST(RunEta, TheInelasticGasCountsCollisionsAndCrossings) {
  const double c = 1000 * std::pow(100.0, 0.2), c_end = c * std::pow(100.0, 0.6);
  const double x = 3000 * std::pow(100.0, 0.1), x_end = x * std::pow(100.0, 0.1);
  const RunEta eta = inelastic_run(0.1, true);
  EXPECT_NEAR(eta.event_rate(), kRate, 1e-9 * kRate);
  EXPECT_NEAR(eta.expected_events(1e4), c_end + x_end, 1e-9 * (c_end + x_end));
  EXPECT_NEAR(eta.seconds_left(1e4), (c_end + x_end - c - x) / kRate, 1e-9 * c_end / kRate);
  const double y = 3000 * std::pow(100.0, 0.7), y_end = y * std::exp(log_growth(100, 1e4, 0.7, 0.4, INFINITY, 1, 0));
  EXPECT_NEAR(inelastic_run(0.7, true).expected_events(1e4), c_end + y_end, 1e-9 * (c_end + y_end));
  EXPECT_GT(y_end, y * std::pow(100.0, 0.4));  // the floor, reached on the way
  const RunEta without = inelastic_run(0.1, false);
  EXPECT_TRUE(std::isnan(without.expected_events(1e4)));
  EXPECT_NEAR(without.seconds_left(1e4), (c_end - c) / without.collision_rate(), 1e-9 * c_end / kRate);
  // Aggregation keeps counting merges alone (its crossings are not modelled).
  RunEta ba = run_eta_for(gas("aggregation", 1e6, 0.208, 1, 0), Geometry(3));
  for (int k = -40; k <= 40; ++k) ba.add({std::pow(10.0, k / 20.0), 1.0 + k + 40, 1.0, 10.0 * (1 + k + 40)});
  EXPECT_TRUE(std::isnan(ba.expected_events(1e4)));
}

// Outputs still due: 3 dumps of a gas (size 1) at the latest dump's cost
// (3 s, after one of 1 s); the checkpoints, one per 300 s of the 600 s the
// engine still needs and the last, at the latest dump's cost while none is
// written, then at the latest checkpoint's (5 s); an interval of 0 (a
// checkpoint after every slice) counts as one per second.
TEST(RunEta, OutputsStillDueCostWhatTheLatestOfTheirKindCost) {
  OutputCost dumps, checkpoints;
  const std::vector<double> three(3, 1.0);
  EXPECT_EQ(output_seconds_left(three, 600, 300, dumps, checkpoints), 0);
  dumps.add(1), dumps.add(3);
  EXPECT_DOUBLE_EQ(output_seconds_left(three, 600, 300, dumps, checkpoints), 3 * 3 + 3 * 3);
  checkpoints.add(5);
  EXPECT_DOUBLE_EQ(output_seconds_left(three, 600, 300, dumps, checkpoints), 3 * 3 + 3 * 5);
  EXPECT_DOUBLE_EQ(output_seconds_left({}, 10, 0, dumps, checkpoints), 11 * 5);
}

// Aggregation's dumps shrink: 4 s at 1e6 aggregates, 2 s at 2.5e5 give
// seconds ~ size^0.5, so one of 62,500 is expected to take 1 s (the latest,
// 2 s, times 0.25^0.5), whatever the older outputs' level was. A cost that
// rises as the size falls (the machine's load) is not extrapolated: the
// latest stands. Only the latest six outputs are fitted.
TEST(RunEta, ADumpCostsWhatItsSizeSays) {
  OutputCost dumps;
  EXPECT_EQ(dumps.expected(1e6, 7), 7);
  dumps.add(4, 1e6), dumps.add(2, 2.5e5);
  EXPECT_NEAR(dumps.expected(62500, 0), 1, 1e-12);
  EXPECT_NEAR(output_seconds_left({62500, 62500}, 0, 300, dumps, OutputCost()), 2 * 1 + 2, 1e-12);
  OutputCost loaded;
  loaded.add(1, 1e6), loaded.add(2, 2.5e5);
  EXPECT_EQ(loaded.expected(62500, 0), 2);
  for (int i = 0; i < 6; ++i) loaded.add(3, 2.5e5 / (i + 1));  // the latest six: the same cost at every size
  EXPECT_NEAR(loaded.expected(1, 0), 3, 1e-12);
}

TEST(RunEta, UnknownUntilAWholeFitWindowAndSamplesStayLogSpaced) {
  RunEta eta(INFINITY);  // C = 1000 t, as in AGasThatDoesNotCoolIsExtrapolatedExactly
  EXPECT_TRUE(std::isnan(eta.seconds_left(10)));
  eta.add({1, 1000, 1000 / kRate});
  eta.add({2, 2000, 2000 / kRate});
  EXPECT_TRUE(std::isnan(eta.seconds_left(10)));  // t = 1 .. 2 is not yet a factor 3 of t
  // A million samples over three decades, linearly spaced: the estimate
  // stays that of the whole run (the last sample is always the newest).
  for (int i = 1; i <= 1000000; ++i) {
    const double t = 2 + i * 1e-3;
    eta.add({t, 1000 * t, 1000 * t / kRate});
  }
  EXPECT_NEAR(eta.expected_collisions(1e4), 1e7, 1e-6 * 1e7);
}

// The knee is the mean-field crossover t ~ L^z, z = (d + 2)/2: a square of
// side L reaches it when a cube of side L^(4/5) does (L^2 = (L^0.8)^(5/2)).
TEST(RunEta, TheKneeIsTheCrossoverOfTheBoxsDimension) {
  RunEta disks(100);
  disks.set_dimension(2);
  const double in_2d = power_law_run(disks, 0.8).expected_collisions(1e6);
  const double in_3d = power_law_run(RunEta(std::pow(100.0, 0.8)), 0.8).expected_collisions(1e6);
  EXPECT_NEAR(in_2d / in_3d, 1, 1e-12);
  EXPECT_LT(in_2d, power_law_run(RunEta(100), 0.8).expected_collisions(1e6));
}

}  // namespace
}  // namespace coolgas
