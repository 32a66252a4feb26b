// eta_replay RUN.h5 ...: the ETA rule of simulate/run/run_eta.h replayed on
// finished runs' cumulative collisions C(t) (/observables/collisions; the
// rule: tests/support/eta_replay.h). Printed per run: the ratio (collisions
// expected still) / (collisions really left) between 10 % and 90 % of the
// run's collisions, its smallest and largest value, where they occur, and
// the ratio at 10 %, 20 %, ... 90 %; for the run as it is and as if it had
// ended at t = 1e3, 1e4, ... The program feeds
// RunEta far more often (every slice of events) than the observables' rows
// (20 a decade by default); the rule keeps one sample per 1 % of t and fits
// over a factor 3 of t, about 10 rows here.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/trajectory/layout.h"
#include "common/trajectory/run_info.h"
#include "tests/support/eta_replay.h"

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
    for (std::size_t end : coolgas::test::replay_ends(c.time)) {
      const coolgas::test::EtaReplay r = coolgas::test::replay_eta(c.time, c.value, end, info.params);
      std::printf("%s\t%.4g\t%s\t%.4g\t%.3f\t%.3g\t%.3f\t%.3g\t", path.c_str(), info.params.L,
                  info.params.model.c_str(), c.time[end], r.lo, r.t_lo, r.hi, r.t_hi);
      for (double d : r.at_decile) std::printf(" %.2f", d);
      std::printf("\n");
    }
  }
  return 0;
}
