#include "simulate/start/rsa_disks.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "common/tsv.h"
#include "simulate/engine/cell_grid.h"
#include "common/geometry.h"

namespace coolgas {

namespace {

// Trials in a row without a free place after which the packing counts as
// saturated: at phi = 0.45 about one trial in 40 succeeds.
constexpr std::int64_t kMaxFailuresInARow = std::int64_t(1) << 24;
// As in 3D (rsa_voxels.cc): below this density cells of the mean spacing,
// not of one diameter, so a dilute square needs no more cells than disks.
constexpr double kWideDiskCellsBelowPhi = 0.1;

double disk_cell_width(double L, std::int64_t N) {
  const bool dilute = N > 0 && Geometry(2).covered_fraction(double(N), L) < kWideDiskCellsBelowPhi;
  const double most = L / 3.0 / (1.0 + 1e-6);  // three cells per side, with CellGrid's margin
  return dilute ? std::max(1.0, std::min(std::sqrt(L * L / double(N)), most)) : 1.0;
}

}  // namespace

void place_random_disks(Particles& p, std::int64_t N, Random& rng, InterruptFlag interrupt,
                        const PlacementReport& report) {
  const double L = p.L, half = L / 2, top = std::nextafter(L, 0.0);
  CellGrid grid(L, disk_cell_width(L, N), std::size_t(N), Geometry(2));  // the scene checked that the square fits it
  const auto image = [&](double d) { return d > half ? d - L : (d < -half ? d + L : d); };
  static constexpr int kLo[3] = {-1, -1, 0}, kHi[3] = {1, 1, 0};
  std::int64_t placed = 0, failures = 0;
  for (std::int64_t trial = 0; placed < N; ++trial) {
    if ((trial & 4095) == 0) {
      throw_if_interrupted(interrupt);
      if (report) report(placed);
    }
    const Vec3 x{std::min(rng.uniform() * L, top), std::min(rng.uniform() * L, top), 0.0};
    const int cell = grid.cell_of(x.x, x.y, 0.0);
    bool free = true;
    for_each_neighbour_cell(grid.cells_per_side(), L, grid.coord(cell), kLo, kHi, [&](const NeighbourCell& nb) {
      for (int j = grid.first(nb.index); j >= 0 && free; j = grid.next(j)) {
        const double dx = image(p.r[std::size_t(j)].x - x.x), dy = image(p.r[std::size_t(j)].y - x.y);
        free = dx * dx + dy * dy >= 1.0;
      }
    });
    if (!free) {
      if (++failures < kMaxFailuresInARow) continue;
      throw InputError("random sequential addition of disks saturated at phi = " +
                       format_number(Geometry(2).covered_fraction(double(placed), L)) + " (" + std::to_string(placed) +
                       " of " + std::to_string(N) + " placed); lower system.phi");
    }
    failures = 0;
    p.r[std::size_t(placed)] = x;
    grid.insert(int(placed), cell);
    ++placed;
  }
}

}  // namespace coolgas
