// The wall time a cooling-gas run still needs, for the progress line: the
// collisions still expected, divided by the recent collision rate (per
// second spent in the engine: dump and checkpoint I/O excluded).
//
// The collisions still expected come from the run so far. The local exponent
// a of the cumulative collisions C(t) (the slope of ln C on ln t, fitted over
// the last factor 3 of t) is carried on as a homogeneous gas would carry it:
// under Haff's law C ~ ln(1 + t/tau), so a falls from 1 towards 0 along
// x/((1 + x) ln(1 + x)), x = t/tau, with tau set by the measured a. Two
// regimes of the paper's gas bound it (Pathak et al. 2014): before
// t = 0.5 L^(5/2) the clustering regime, where a stays at least a floor
// (0.6 for the paper's gas; clustering_floor() for others), and
// beyond it the finite-size regime, where a is at most 0.35 (t/t_knee)^-0.35
// (the constants and how they were chosen: run_eta.cc). A run that has not yet covered a
// factor 3 of t is not extrapolated. A gas that does not cool (a >= 1)
// keeps its exponent; pass L = INFINITY where no finite-size regime comes.
//
// Measured by replaying finished runs (tests/bench/eta_replay.cc) and live
// with tests/bench/eta_check.py (tests/bench/README.md, "ETA").
// tests/unit/simulate/run/run_eta_test.cc checks the rule on closed forms.
#pragma once
#include <cmath>
#include <vector>

#include "common/trajectory/run_parameters.h"

namespace coolgas {

struct RunSample {
  double t = 0;             // simulated time
  double collisions = 0;    // cumulative, since t = 0
  double busy_seconds = 0;  // wall seconds spent advancing the engine so far
};

class RunEta {
 public:
  // `most_collisions`: a bound C(t) cannot pass (ballistic aggregation: one
  // merge per aggregate lost, so N - 1). `clustering`: the floor of the
  // exponent before the knee.
  explicit RunEta(double L, double most_collisions = INFINITY, double clustering = 0.5)
      : L_(L), most_(most_collisions), clustering_(clustering) {}
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
  double L_, most_, clustering_;
  std::vector<RunSample> samples_;
};

// The floor of the exponent in the clustering regime of an inelastic gas
// with the delta cut-off (the paper's Eq. 1): 0.6 at phi = 0.208, r0 = 0.1,
// delta = 1e-4, higher for a denser gas, a smaller r0 or a smaller delta
// (run_eta.cc says how much, and from which runs).
double clustering_floor(double phi, double r0, double delta);

// The ETA of a run of these parameters: an elastic gas has no finite-size
// regime, aggregation at most N - 1 merges, the inelastic gas its own
// clustering floor; other cooling gases (viscoelastic) the floor 0.5.
RunEta run_eta_for(const RunParameters& p);

// ln(C(t_end) / C(t)) for a local exponent that is a at t and then falls
// as under Haff's law, is at least `clustering` before t_knee and at most
// tail (t'/t_knee)^-tail_fall at t' beyond it (the rule of RunEta; in closed
// form before the knee, by midpoints beyond it).
double log_growth(double t, double t_end, double a, double clustering, double t_knee, double tail,
                  double tail_fall);

}  // namespace coolgas
