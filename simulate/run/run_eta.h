// The wall time a cooling-gas run still needs, for the progress line: the
// collisions still expected, divided by the measured collision rate (per
// second spent in the engine: dump and checkpoint I/O excluded).
//
// The collisions still expected come from the run so far: the cumulative
// collisions C(t) are fitted by a power law over the last decade of t (least
// squares of ln C on ln t) and extrapolated to t_end; beyond t = 2 L^(5/2),
// well into the finite-size regime where E ~ t^-eta (eta = 1.83, Pathak et
// al. 2014) and the collision rate ~ sqrt(E), the exponent is at most
// 1 - eta/2. Progress measured in log t, as before, said "~0s" with 80 % of
// the collisions left. Measured on five runs (L = 12-34): after the first
// tenth of the collisions, the estimate of those left is within 0.33-2.45
// times the truth (tests/unit/simulate/run/run_eta_test.cc checks the rule).
#pragma once
#include <vector>

namespace coolgas {

struct RunSample {
  double t = 0;             // simulated time
  double collisions = 0;    // cumulative, since t = 0
  double busy_seconds = 0;  // wall seconds spent advancing the engine so far
};

class RunEta {
 public:
  explicit RunEta(double L) : L_(L) {}
  // Keeps samples log-spaced in t (one per 1 % of t at most).
  void add(const RunSample& s);
  // Collisions per busy second between the first and the last sample; 0 if unknown.
  double collision_rate() const;
  // The cumulative collisions expected at t_end; NaN if not yet known.
  double expected_collisions(double t_end) const;
  // Wall seconds still needed to reach t_end; NaN if not yet known.
  double seconds_left(double t_end) const;

 private:
  double L_;
  std::vector<RunSample> samples_;
};

}  // namespace coolgas
