// Speed of coolgas-shape on the paper's largest system: N = 8e6 uniformly
// random centres (phi = 0.208, L = 272.1, 272^3 cells), one frame, file
// reading excluded: labelling, the unwrapping walk over every cluster's cells,
// the gyration tensors and eigenvalues of all clusters, and the d_f fit.
// Prints the median of 3 repeats, wall-clock and thread CPU time.
#include <cmath>
#include <cstdio>
#include <vector>

#include "analyze/shape/mass_radius.h"
#include "common/random.h"
#include "tests/bench/median_timing.h"

int main() {
  constexpr std::int64_t kN = 8'000'000;
  const double L = std::cbrt(kN * M_PI / (6 * 0.208));
  coolgas::Random rng(1);
  std::vector<double> pos(3 * kN);
  for (double& x : pos) x = L * rng.uniform();
  const coolgas::ClusterGrid grid(L, coolgas::Geometry(3));
  coolgas::ClusterShapes shapes;
  const coolgas::Window fit = coolgas::parse_window("10:", "--fit-mass");
  coolgas::MassRadius mr;
  std::size_t clusters = 0;
  const auto t = coolgas::bench::median_time(3, [&] {
    const auto s = shapes.of_particles(grid, pos);
    clusters = s.size();
    mr = coolgas::mass_radius(s, 10, fit);
  });
  {  // where the time goes
    coolgas::ClusterLabeller lab;
    coolgas::ClusterUnwrapping unwrap;
    const auto tl = coolgas::bench::median_time(3, [&] { lab.label(grid, pos); });
    const auto tr = coolgas::bench::median_time(3, [&] { lab.ranked(); });
    const auto tu = coolgas::bench::median_time(3, [&] { unwrap.build(grid, lab, pos); });
    std::printf("  of which: labelling %.0f ms cpu, ranking %.0f ms cpu, unwrapping walk (ranking included) %.0f ms cpu\n",
                1e3 * tl.cpu, 1e3 * tr.cpu, 1e3 * tu.cpu);
  }
  std::printf("shapes + d_f, uniform N=%lld grid=%d^3: %.0f ms wall, %.0f ms cpu (%zu clusters, d_f = %.2f, wrapping %.0f%%)\n",
              (long long)kN, grid.per_side(), 1e3 * t.wall, 1e3 * t.cpu, clusters, mr.d_f, 100 * mr.wrapping_fraction);
  return 0;
}
