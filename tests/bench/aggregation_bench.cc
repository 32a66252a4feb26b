// Ballistic aggregation speed, workload W3 of the effects issue: N = 10^6
// unit spheres at phi = 0.208 (an equilibrated fluid, as coolgas-simulate
// starts it) aggregating until 1 % of the aggregates remain. Reports the
// wall time of the aggregation (set-up excluded), merges per second, events
// per merge (grid rebuilds and chain merges are included in the time).
// usage: aggregation_bench [N] [phi] [remaining_fraction]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"

int main(int argc, char** argv) {
  using clock = std::chrono::steady_clock;
  coolgas::Scene s;
  s.N = argc > 1 ? std::atoll(argv[1]) : 1000000;
  s.phi = argc > 2 ? std::atof(argv[2]) : 0.208;
  const double remain = argc > 3 ? std::atof(argv[3]) : 0.01;
  s.L = std::cbrt(double(s.N) * M_PI / (6.0 * s.phi));
  s.t_end = 1e12;
  s.model = coolgas::CollisionModel::kAggregation;
  const auto t_setup = clock::now();
  coolgas::AggregationEngine e(coolgas::initial_state(s), coolgas::AggregateState::unit_spheres(std::size_t(s.N)), 0.0);
  const double setup = std::chrono::duration<double>(clock::now() - t_setup).count();
  const auto target = static_cast<std::size_t>(std::ceil(remain * double(s.N)));
  const auto t0 = clock::now();
  double t = 0.1;
  while (e.aggregates() > target) {
    // Stops on a log grid (as a run with observables would); each stop costs nothing.
    e.run_until(t, std::int64_t(1) << 40, nullptr);
    t *= 1.05;
  }
  const double wall = std::chrono::duration<double>(clock::now() - t0).count();
  const auto& c = e.counters();
  std::printf("W3\tN=%lld\tphi=%.3f\tremaining=%zu\tt=%.4g\tmerges=%lld\twall=%.2fs\tmerges/s=%.0f"
              "\tevents/merge=%.2f\tlargest_diameter=%.3g\tsetup=%.2fs\n",
              (long long)s.N, s.phi, e.aggregates(), e.now(), (long long)c.collisions, wall,
              double(c.collisions) / wall, double(c.events) / double(c.collisions), e.largest_diameter(), setup);
}
