// The wall time a cooling-gas run still needs, for the progress line: the
// engine's work still expected, divided by its recent rate (per second spent
// in the engine), plus the dumps and checkpoints still due at the cost
// measured for those already written.
//
// The engine's work is counted in collisions or, where the cell crossings
// are modelled (the inelastic gas), in events: a collision and a crossing
// cost about the same (measured: 1.0-1.4e6 events per busy second before and
// after a dilute gas clusters, while its collisions per second double), and
// crossings, which follow the temperature, grow more slowly than the
// collisions inside clusters (tests/bench/history.md, "ETA").
//
// The collisions still expected come from the run so far. The local exponent
// a of the cumulative collisions C(t) (the slope of ln C on ln t, fitted over
// the last factor 3 of t) is carried on as a homogeneous gas would carry it:
// under Haff's law C ~ ln(1 + t/tau), so a falls from 1 towards 0 along
// x/((1 + x) ln(1 + x)), x = t/tau, with tau set by the measured a. Two
// regimes of the paper's gas bound it (Pathak et al. 2014): before
// t = 0.5 L^z, z = (d + 2)/2 (5/2 in 3D, the mean-field crossover), the clustering regime, where a stays at least a floor
// (0.6 for the paper's gas; clustering_floor() for others), and
// beyond it the finite-size regime, where a is at most 0.35 (t/t_knee)^-0.35
// (the constants and how they were chosen: run_eta.cc). The crossings X(t)
// are carried on the same way with the floor crossing_floor(phi) (0.4 =
// 1 - theta/2 for the paper's gas: a crossing rate ~ sqrt(E), E ~ t^-theta,
// theta = 6/5 in the clustered gas, the paper's result), or their exponent
// now if it is lower, and no finite-size fall. A run that has not yet
// covered a factor 3 of t is not extrapolated. A gas that does not cool
// (a >= 1) keeps its exponent; pass L = INFINITY where no finite-size regime
// comes.
//
// Ballistic aggregation extrapolates the aggregates left, n = N - C, along
// n ~ (1 + t/tau)^-6/5, with tau set by the local exponent of n now: the
// mean-field decay of BA, theta_BA^mf = 2d/(d + 2) = 6/5 (Carnevale et al.
// 1990, as quoted by Pathak et al. 2014, who measure theta_BA = 1.206-1.283
// for phi = 0.208-0.005; n ~ E, each aggregate's kinetic energy staying
// of order T0 as momentum is conserved). Its frames shrink with n, and so
// does the cost of a dump (OutputCost).
//
// The plan of a run before it starts (run_plan.h) is this rule fed with a
// pilot run. Measured by replaying finished runs (tests/bench/eta_replay.cc)
// and live with tests/bench/eta_check.py (the figures: tests/bench/README.md).
// tests/unit/simulate/run/run_eta_test.cc checks the rule on closed forms,
// run_eta_replay_test.cc its accuracy on finished runs (tests/data/eta).
#pragma once
#include <cmath>
#include <vector>

#include "common/geometry.h"
#include "common/trajectory/run_parameters.h"

namespace coolgas {

struct RunSample {
  double t = 0;             // simulated time
  double collisions = 0;    // cumulative, since t = 0
  double busy_seconds = 0;  // wall seconds spent advancing the engine so far
  double events = NAN;      // cumulative events of all kinds (collisions, crossings, stale); NaN if unknown
};

class RunEta {
 public:
  // `most_collisions`: a bound C(t) cannot pass (ballistic aggregation: one
  // merge per aggregate lost, so N - 1). `clustering`: the floor of the
  // exponent before the knee. `crossings`: the floor of the exponent of the
  // events other than collisions, NaN to count the work in collisions alone.
  explicit RunEta(double L, double most_collisions = INFINITY, double clustering = 0.5, double crossings = NAN)
      : L_(L), most_(most_collisions), clustering_(clustering), crossings_(crossings) {}
  // Ballistic aggregation of N particles: the merges are N minus the
  // aggregates left, at most N - 1. The engine's cost per merge changes
  // with a period of `regrid_factor` in the aggregates left (its grid is
  // rebuilt, at a search per aggregate, each time they fall that much), so
  // the rate window spans at least that last factor.
  static RunEta aggregation(double L, double N, double regrid_factor);
  // The dimension d of the box, which sets its finite-size crossover,
  // t ~ L^z with the mean field's z = (d + 2)/2 (3 unless set).
  void set_dimension(int d);
  // Where the finite-size regime of a box of side L begins, kKnee L^z.
  double knee(double L) const;
  // Keeps samples log-spaced in t (one per 1 % of t at most); the last
  // sample is always the newest.
  void add(const RunSample& s);
  // Collisions per busy second over the last quarter of the busy time (the
  // rate changes with the gas and with the machine's load), under
  // aggregation over the last regrid factor of aggregates if that is
  // longer; 0 if unknown.
  double collision_rate() const;
  // The same for events of all kinds; 0 if unknown.
  double event_rate() const;
  // The local exponent of C(t) (least squares of ln C on ln t) over
  // lo <= t <= hi; NaN without two distinct times.
  double exponent(double lo, double hi) const;
  // The cumulative collisions expected at t_end; NaN if not yet known.
  double expected_collisions(double t_end) const;
  // The cumulative events expected at t_end: the collisions expected and the
  // other events carried on with the `crossings` floor; NaN if not modelled
  // or not yet known.
  double expected_events(double t_end) const;
  // Seconds in the engine still needed to reach t_end (in events where they
  // are modelled, else in collisions); NaN if not yet known.
  double seconds_left(double t_end) const;
  // The size of a frame at t (now's, or expected for a later t): the
  // aggregates it holds under aggregation, 1 for a gas (its frames do not
  // change); NaN if not yet known.
  double frame_size(double t) const;

 private:
  // The rate and the local exponent of one cumulative count of the samples.
  using Count = double (*)(const RunSample&);
  double rate_of(Count count) const;
  double exponent_of(Count count, double lo, double hi) const;
  // Aggregation: the merges expected by t_end from the aggregates left.
  double expected_merges(double t_end) const;

  double L_, most_, clustering_, crossings_;
  double crossover_exponent_ = 2.5;  // z of the knee, kKnee L^z
  double aggregates_ = NAN;  // N under aggregation, else NaN
  double regrid_factor_ = 1;  // the rate window's least fall of the aggregates left
  std::vector<RunSample> samples_;
};

// The floor of the exponent of the cell crossings in the clustering regime:
// 1 - theta/2 = 0.4 for theta = 6/5 (the paper's energy decay, t^-theta)
// at the paper's phi = 0.208, lower for a more dilute gas (run_eta.cc says
// how much, and from which runs).
double crossing_floor(double phi);

// The wall seconds outputs of one kind (dumps, checkpoints) took, and the
// size of each (frame_size()): the next one's best guess is the latest's,
// scaled by (size / latest size)^gamma, gamma the slope of ln seconds on
// ln size over the latest few, within [0, 1] (0 while the sizes do not
// differ). Aggregation's dumps get cheaper as aggregates die (their empty
// slots compress away); the latest sets the level as the machine's load
// changes.
class OutputCost {
 public:
  void add(double seconds, double size = 1);
  double latest(double otherwise) const { return recent_.empty() ? otherwise : recent_.back().seconds; }
  // The seconds an output of this size is expected to take; `otherwise`
  // while none is written.
  double expected(double size, double otherwise) const;

 private:
  struct Output {
    double size, seconds;
  };
  std::vector<Output> recent_;  // the latest few, oldest first
};

// Wall seconds the outputs still due take: the dumps of `dump_sizes` (one
// frame_size() per dump still scheduled) at their expected cost, and the
// checkpoints (one per `interval` wall seconds, at least 1 s, of the
// engine's `engine_seconds_left`, and the last) at the latest checkpoint's,
// or the latest dump's while none is written.
double output_seconds_left(const std::vector<double>& dump_sizes, double engine_seconds_left, double interval,
                           const OutputCost& dumps, const OutputCost& checkpoints);

// The floor of the exponent in the clustering regime of an inelastic gas
// with the delta cut-off (the paper's Eq. 1): 0.6 at phi = 0.208, r0 = 0.1,
// delta = 1e-4, higher for a denser gas, a smaller r0 or a smaller delta
// (run_eta.cc says how much, and from which runs).
double clustering_floor(double phi, double r0, double delta);

// The rules each model's row picks (simulate/run/models.h, run_eta_for):
// an elastic gas does not cool (no finite-size regime); a cooling gas with
// the generic floor; the inelastic gas with its clustering and crossing
// floors; ballistic aggregation by the aggregates left.
RunEta eta_without_cooling(const RunParameters& p);
RunEta eta_of_cooling_gas(const RunParameters& p);
RunEta eta_of_inelastic_gas(const RunParameters& p);
RunEta eta_of_aggregation(const RunParameters& p);
// A driven gas (any model with [driving], simulate/engine/driving.h) tends
// to a steady state, where C grows as t, or (elastic) heats, where it grows
// faster: its exponent is held at 1 or more, with no finite-size regime.
// run_eta_for picks it over the model's row whenever the run is driven.
RunEta eta_of_driven_gas(const RunParameters& p);

// ln(C(t_end) / C(t)) for a local exponent that is a at t and then falls
// as under Haff's law, is at least `clustering` before t_knee and at most
// tail (t'/t_knee)^-tail_fall at t' beyond it (the rule of RunEta; in closed
// form before the knee, by midpoints beyond it).
double log_growth(double t, double t_end, double a, double clustering, double t_knee, double tail,
                  double tail_fall);

}  // namespace coolgas
