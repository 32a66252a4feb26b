// Speed of the analysis beyond the paper on its largest system: N = 8e6
// particles at phi = 0.208 (L = 272.1), one frame, file reading excluded
// (cluster_bench measures that):
//   coolgas-fields at cells of 4 sigma (the default: 68^3 cells) and of 2
//   sigma (136^3): the cells' sums, the energies, and the flow split (d r2c
//   FFTs and the sum over modes); and the .vti arrays' vorticity;
//   coolgas-clusters --definition contact (cutoff 1.1): the bonds by the
//   cell list and the union-find;
//   coolgas-structure --rdf: the pairs up to 5 sigma, 50 bins per sigma.
// Uniformly random centres in id order. Prints medians of 5 repeats,
// wall-clock and thread CPU time.
#include <cmath>
#include <cstdio>
#include <vector>

#include "analyze/fields/cell_fields.h"
#include "analyze/fields/fields_table.h"
#include "analyze/fields/flow_split.h"
#include "analyze/fields/tool.h"
#include "analyze/labelling/contact_labeller.h"
#include "analyze/structure/radial_distribution.h"
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
  // Random centres overlap, so the pairs within 1.1 sigma are ~4x an
  // equilibrium fluid's: an upper bound on the work.
  coolgas::ContactLabeller contacts;
  const Timing c = median_time(3, [&] { contacts.label(kL, pos, 1.1, g); });
  std::printf("%-44s %7.0f ms wall, %7.0f ms cpu (%zu clusters)\n", "contact clusters, cutoff 1.1", 1e3 * c.wall,
              1e3 * c.cpu, contacts.clusters());
  coolgas::PairDistances rdf(g, 5, 50);
  const Timing r = median_time(3, [&] {
    rdf.clear();
    rdf.add(kL, pos);
  });
  std::printf("%-44s %7.0f ms wall, %7.0f ms cpu\n", "g(r) to 5 sigma, 50 bins per sigma", 1e3 * r.wall, 1e3 * r.cpu);
  return 0;
}
