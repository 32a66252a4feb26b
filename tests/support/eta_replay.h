// The ETA rule of simulate/run/run_eta.h replayed on a finished run's
// cumulative collisions C(t), as tests/bench/eta_replay and the replay test
// use it. The engine's busy seconds are replaced by the collision count, so
// the "seconds left" RunEta returns are the collisions it still expects, and
// the machine's load plays no part. Looked at between 10 % and 90 % of the
// run's collisions (the cost of a collision is nearly constant through a
// run, so about 10-90 % of its wall time): the ratio (collisions expected
// still) / (collisions really left), its extremes and its value at 10 %,
// 20 %, ... 90 %.
#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include "simulate/run/models.h"
#include "simulate/run/run_eta.h"

namespace coolgas::test {

struct EtaReplay {
  double lo = INFINITY, hi = 0, t_lo = 0, t_hi = 0;
  double at_decile[9] = {};
};

// The run as if it had ended at its row `end` (a run is the same up to any
// time whatever its t_end).
inline EtaReplay replay_eta(const std::vector<double>& time, const std::vector<double>& collisions, std::size_t end,
                            const RunParameters& p) {
  RunEta eta = run_eta_for(p, Geometry(3));  // as coolgas-simulate's
  const double total = collisions[end], t_end = time[end];
  EtaReplay r;
  int next_decile = 1;
  for (std::size_t i = 0; i < end; ++i) {
    eta.add({time[i], collisions[i], collisions[i]});
    const double done = collisions[i] / total, left = total - collisions[i];
    const double expected = eta.seconds_left(t_end);
    if (done < 0.1 || !(left > 0) || !std::isfinite(expected)) continue;
    const double ratio = expected / left;
    while (next_decile <= 9 && done >= next_decile / 10.0) r.at_decile[next_decile++ - 1] = ratio;
    if (done > 0.9) continue;
    if (ratio < r.lo) r.lo = ratio, r.t_lo = time[i];
    if (ratio > r.hi) r.hi = ratio, r.t_hi = time[i];
  }
  return r;
}

// The rows a run is replayed to: t = 1e3, 1e4, ... below its end, and its end.
inline std::vector<std::size_t> replay_ends(const std::vector<double>& time) {
  std::vector<std::size_t> ends;
  for (std::size_t i = 0; i + 1 < time.size(); ++i) {
    const double decade = std::round(std::log10(time[i]));
    if (time[i] >= 1e3 && time[i] == std::pow(10.0, decade)) ends.push_back(i);
  }
  ends.push_back(time.size() - 1);
  return ends;
}

}  // namespace coolgas::test
