// The wall time a cooling-gas run still needs, for the progress line: the
// collisions still expected, divided by the recent collision rate (per
// second spent in the engine: dump and checkpoint I/O excluded).
//
// The collisions still expected come from the run so far. The cumulative
// collisions C(t) of a cooling gas follow a power law whose exponent a (the
// local slope of ln C on ln t) falls from 1 (before the first collisions
// cool the gas) through ~0.4 (E ~ t^-6/5: the rate per particle ~ sqrt(E))
// to below 0.1 deep in the finite-size regime (Pathak et al. 2014); dilute
// gases fall for decades. So a is fitted over the last factor 3 of t, and
// again over the factor before: a falling exponent goes on falling at that
// pace (in ln t), down to 0.25; before t = 0.5 L^(5/2) it is at least 0.4,
// that of the clustering regime, and beyond it at most 0.2
// (the constants and how they were chosen: run_eta.cc). A run that has not
// yet covered a factor 3 of t is not extrapolated.
//
// Measured with tests/bench/eta_check.py (tests/bench/README.md, "ETA"):
// after the first tenth of a run, the ETA / the time really left.
// tests/unit/simulate/run/run_eta_test.cc checks the rule on closed forms.
#pragma once
#include <cmath>
#include <vector>

namespace coolgas {

struct RunSample {
  double t = 0;             // simulated time
  double collisions = 0;    // cumulative, since t = 0
  double busy_seconds = 0;  // wall seconds spent advancing the engine so far
};

class RunEta {
 public:
  // `most_collisions`: a bound C(t) cannot pass (ballistic aggregation: one
  // merge per aggregate lost, so N - 1).
  explicit RunEta(double L, double most_collisions = INFINITY) : L_(L), most_(most_collisions) {}
  // Keeps samples log-spaced in t (one per 1 % of t at most); the last
  // sample is always the newest.
  void add(const RunSample& s);
  // Collisions per busy second over the last quarter of the busy time (the
  // rate changes with the gas and with the machine's load); 0 if unknown.
  double collision_rate() const;
  // The local exponent of C(t) (least squares of ln C on ln t) over
  // lo <= t <= hi; NaN without two distinct times.
  double exponent(double lo, double hi) const;
  // The cumulative collisions expected at t_end; NaN if not yet known.
  double expected_collisions(double t_end) const;
  // Wall seconds still needed to reach t_end; NaN if not yet known.
  double seconds_left(double t_end) const;

 private:
  double L_, most_;
  std::vector<RunSample> samples_;
};

// ln(C(t_end) / C(t)) for a local exponent that starts at a, changes by
// `trend` per unit of ln t but not below min(floor, a), and is at most
// `tail` beyond t_knee (the rule of RunEta, in closed form per piece).
double log_growth(double t, double t_end, double a, double trend, double floor, double t_knee, double tail);

}  // namespace coolgas
