// Speed of coolgas-fields on the paper's largest system: N = 8e6 particles at
// phi = 0.208 (L = 272.1), one frame, file reading excluded (cluster_bench
// measures that), at cells of 4 sigma (the default: 68^3 cells) and of 2
// sigma (136^3): the cells' sums, the energies, and the flow split (d r2c
// FFTs and the sum over modes); and the slab and the .vti arrays' vorticity.
// Uniformly random centres in id order. Prints medians of 5 repeats,
// wall-clock and thread CPU time.
#include <cmath>
#include <cstdio>
#include <vector>

#include "analyze/fields/cell_fields.h"
#include "analyze/fields/fields_table.h"
#include "analyze/fields/flow_split.h"
#include "analyze/fields/tool.h"
#include "common/random.h"
#include "tests/bench/median_timing.h"

namespace {

constexpr std::int64_t kN = 8'000'000;
constexpr double kPhi = 0.208;
const double kL = std::cbrt(kN * M_PI / (6 * kPhi));

using coolgas::bench::median_time;
using coolgas::bench::Timing;

void report(const char* what, int n, const Timing& t) {
  std::printf("%-44s %4d^3 cells %7.0f ms wall, %7.0f ms cpu\n", what, n, 1e3 * t.wall, 1e3 * t.cpu);
}

}  // namespace

int main() {
  const coolgas::Geometry g(3);
  std::printf("N = %lld, phi = %.3f, L = %.2f\n", (long long)kN, kPhi, kL);
  coolgas::Random rng(1);
  std::vector<double> pos(3 * kN), vel(3 * kN);
  for (double& x : pos) x = kL * rng.uniform();
  for (double& v : vel) v = rng.normal();
  for (double cell : {4.0, 2.0}) {
    const int n = coolgas::field_cells(kL, cell, g, 1e12);
    coolgas::FourierGrid grid(n, g);
    report("a dump's row (cells, energies, flow split)", n, median_time(5, [&] {
             coolgas::fields_block(coolgas::FieldsTable::kSeries, grid, 0, kL, pos, vel, {});
           }));
    coolgas::CellFields f;
    report("  of which: the cells' sums", n, median_time(3, [&] { f = coolgas::cell_fields(n, g, kL, pos, vel, {}); }));
    const coolgas::FieldEnergies e = coolgas::field_energies(f);
    report("  of which: the flow split (3 FFTs, modes)", n,
           median_time(3, [&] { coolgas::flow_split(f, e.temperature, grid); }));
    double sum = 0;
    report("every cell's vorticity (the .vti array)", n, median_time(3, [&] {
             for (std::int64_t c = 0; c < f.cells(); ++c) sum += coolgas::cell_vorticity(f, c)[2];
           }));
    std::printf("(E_T / noise = %.4f)\n", coolgas::flow_split(f, e.temperature, grid).transverse /
                                            coolgas::flow_split(f, e.temperature, grid).transverse_noise);
  }
  return 0;
}
