// Ballistic aggregation speed. Workload W3 of the effects issue: N = 10^6
// unit spheres at phi = 0.208 (an equilibrated fluid, as coolgas-simulate
// starts it) aggregating until 1 % of the aggregates remain. Workload W3b:
// the paper's long runs, N = 8×10^6 at phi = 0.005 and 0.208 to t = 10^5 or
// until the largest aggregate reaches half the box (where the engine stops).
// Reports the wall time of the aggregation (set-up excluded), merges per
// second, events per merge (grid rebuilds and chain merges are included in
// the time), why it ended and the peak memory; a long run (t_end given)
// also prints a progress line each time t doubles.
// usage: aggregation_bench [N] [phi] [remaining_fraction] [t_end]
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

long peak_memory_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024;  // Linux reports kilobytes
}

void report(const char* label, double phi, const coolgas::AggregationEngine& e, double wall, double setup,
            const char* end) {
  const auto& c = e.counters();
  std::printf("%s\tN=%zu\tphi=%.3f\tL=%.4g\tremaining=%zu\tt=%.4g\tmerges=%lld\twall=%.2fs\tmerges/s=%.0f"
              "\tevents/merge=%.2f\tlargest_diameter=%.3g\tsetup=%.2fs\tend=%s\tpeak_memory=%ldMB\n",
              label, e.size(), phi, e.box(), e.aggregates(), e.now(), (long long)c.collisions, wall,
              double(c.collisions) / wall, double(c.events) / double(c.collisions), e.largest_diameter(), setup, end,
              peak_memory_mb());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  coolgas::Scene s;
  s.N = argc > 1 ? std::atoll(argv[1]) : 1000000;
  s.phi = argc > 2 ? std::atof(argv[2]) : 0.208;
  const double remain = argc > 3 ? std::atof(argv[3]) : 0.01;
  const double t_end = argc > 4 ? std::atof(argv[4]) : 0;  // 0: no time limit
  s.L = std::cbrt(double(s.N) * M_PI / (6.0 * s.phi));
  s.t_end = 1e12;
  s.model = coolgas::CollisionModel::kAggregation;
  const auto t_setup = Clock::now();
  coolgas::AggregationEngine e(coolgas::initial_state(s), coolgas::AggregateState::unit_spheres(std::size_t(s.N)), 0.0, {}, coolgas::Geometry(3));
  const double setup = seconds_since(t_setup);
  const auto target = static_cast<std::size_t>(std::ceil(remain * double(s.N)));
  const char* label = t_end > 0 ? "W3b" : "W3";
  const char* end = "remaining";
  const auto t0 = Clock::now();
  double t = 0.1, next_report = 1;
  try {
    while (e.aggregates() > target) {
      if (t_end > 0 && e.now() >= t_end) {
        end = "t_end";
        break;
      }
      // Stops on a log grid (as a run with observables would); each stop costs nothing.
      e.run_until(t_end > 0 ? std::min(t, t_end) : t, std::int64_t(1) << 40, nullptr);
      t *= 1.05;
      if (t_end > 0 && e.now() >= next_report) {
        report("progress", s.phi, e, seconds_since(t0), setup, "-");
        next_report *= 2;
      }
    }
  } catch (const coolgas::RunStopped&) {
    end = "half_box";  // the largest aggregate reached L/2: as far as the box allows
  }
  report(label, s.phi, e, seconds_since(t0), setup, end);
}
