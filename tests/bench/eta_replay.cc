// eta_replay RUN.h5 ...: the ETA rule of simulate/run/run_eta.h replayed on
// finished runs. Each run's cumulative collisions C(t) (/observables/collisions)
// are fed to RunEta row by row with the engine's busy seconds replaced by the
// collision count, so the "seconds left" it returns are the collisions it
// still expects, and the machine's load plays no part. Printed per run: the
// ratio (collisions expected still) / (collisions really left) at the rows
// between 10 % and 90 % of the run's collisions (the cost of a collision is
// nearly constant through a run, so about 10-90 % of its wall time): its
// smallest and largest value, where they occur, and the ratio at 10 %, 20 %,
// ... 90 %; for the run as it is and as if it had ended at t = 1e3, 1e4, ...
// (a run is the same up to any time whatever its t_end). The program feeds
// RunEta far more often (every slice of events) than the observables' rows
// (20 a decade by default); the rule keeps one sample per 1 % of t and fits
// over a factor 3 of t, about 10 rows here.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/trajectory/layout.h"
#include "common/trajectory/run_info.h"
#include "simulate/run/run_eta.h"

namespace {

using coolgas::ObservableSeries;
using coolgas::RunEta;

struct Replay {
  double lo = INFINITY, hi = 0, t_lo = 0, t_hi = 0;
  double at_decile[9] = {};
};

// The run as if it had ended at its row `end` (a run is the same up to any
// time whatever its t_end).
Replay replay(const ObservableSeries& c, std::size_t end, const coolgas::RunParameters& p) {
  RunEta eta = coolgas::run_eta_for(p);  // as coolgas-simulate's
  const double total = c.value[end], t_end = c.time[end];
  Replay r;
  int next_decile = 1;
  for (std::size_t i = 0; i < end; ++i) {
    eta.add({c.time[i], c.value[i], c.value[i]});
    const double done = c.value[i] / total, left = total - c.value[i];
    const double expected = eta.seconds_left(t_end);
    if (done < 0.1 || !(left > 0) || !std::isfinite(expected)) continue;
    const double ratio = expected / left;
    while (next_decile <= 9 && done >= next_decile / 10.0) r.at_decile[next_decile++ - 1] = ratio;
    if (done > 0.9) continue;
    if (ratio < r.lo) r.lo = ratio, r.t_lo = c.time[i];
    if (ratio > r.hi) r.hi = ratio, r.t_hi = c.time[i];
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: eta_replay RUN.h5 ...  (finished coolgas-simulate runs)\n");
    return 2;
  }
  std::printf("run\tL\tmodel\tt_end\tmin\tt_at_min\tmax\tt_at_max\tat_10_20_..._90_percent\n");
  for (int a = 1; a < argc; ++a) {
    const std::string path = argv[a];
    const auto info = coolgas::read_run_info(path);
    const auto c = coolgas::read_observable(path, coolgas::layout::kCollisions);
    // Ends at t = 1e3, 1e4, ... below the run's own, and its own.
    std::vector<std::size_t> ends;
    for (std::size_t i = 0; i + 1 < c.time.size(); ++i) {
      const double decade = std::round(std::log10(c.time[i]));
      if (c.time[i] >= 1e3 && c.time[i] == std::pow(10.0, decade)) ends.push_back(i);
    }
    ends.push_back(c.time.size() - 1);
    for (std::size_t end : ends) {
      const Replay r = replay(c, end, info.params);
      std::printf("%s\t%.4g\t%s\t%.4g\t%.3f\t%.3g\t%.3f\t%.3g\t", path.c_str(), info.params.L,
                  info.params.model.c_str(), c.time[end], r.lo, r.t_lo, r.hi, r.t_hi);
      for (double d : r.at_decile) std::printf(" %.2f", d);
      std::printf("\n");
    }
  }
  return 0;
}
