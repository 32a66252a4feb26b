// When the progress line shows its time left. Early in a run the estimate
// extrapolates a few seconds of a gas whose rates still change fast, and
// measured live it read 15 min, 4 h and 9 h 50 min in the first 2-8 % of
// runs that took 35-45 s. So the line says "estimating..." until either
//   - the run so far is at least kSeenFraction of the whole it predicts
//     (the estimate extrapolates at most 20 times what was seen), or
//   - the predicted whole (elapsed + time left) has stayed within a factor
//     kSteadyFactor for the last kSteadySeconds of wall time (and a quarter
//     of the run so far, if longer): a long run's estimate, once steady,
//     is shown long before 5 % of it has passed.
// Once shown, the estimate stays shown.
#pragma once
#include <deque>

namespace coolgas {

class EtaGate {
 public:
  static constexpr double kSeenFraction = 0.05;
  static constexpr double kSteadyFactor = 1.5;
  static constexpr double kSteadySeconds = 5;

  // The estimate `left` [s] at `elapsed` [s] of wall time (NaN: none yet).
  // Whether it is to be shown.
  bool show(double elapsed, double left);

 private:
  struct Guess {
    double elapsed, whole;
  };
  std::deque<Guess> recent_;  // the predicted wholes over the steadiness window
  bool open_ = false;
};

}  // namespace coolgas
