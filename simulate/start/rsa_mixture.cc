#include "simulate/start/rsa_mixture.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "common/error.h"
#include "common/tsv.h"
#include "simulate/engine/cell_grid.h"

namespace coolgas {

namespace {

// Trials in a row without a free place after which the packing counts as
// saturated (as for disks, rsa_disks.cc).
constexpr std::int64_t kMaxFailuresInARow = std::int64_t(1) << 24;

// Rods of several lengths on the ring: the gaps between neighbours are
// uniform on the simplex {gaps >= 0, sum = L - total length} whatever their
// order, and every cyclic order is equally likely, so a random order, the
// spacings of sorted uniform points on the free length, each rod moved on by
// the lengths before it, and a random turn are an exact equilibrium draw.
void place_rod_mixture(Particles& p, const std::vector<double>& diameter, Random& rng, InterruptFlag interrupt,
                       const PlacementReport& report) {
  const std::size_t n = p.size();
  std::vector<std::int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  for (std::size_t i = 0; i + 1 < n; ++i)
    std::swap(order[i], order[i + std::size_t(rng.below(std::uint64_t(n - i)))]);
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) total += diameter[p.species[i]];
  const double L = p.L, free_length = L - total;
  std::vector<double> u(n);
  for (std::size_t k = 0; k < n; ++k) {
    if ((k & 0xffff) == 0) {
      throw_if_interrupted(interrupt);
      if (report) report(std::int64_t(k));
    }
    u[k] = rng.uniform() * free_length;
  }
  std::sort(u.begin(), u.end());
  const double offset = rng.uniform() * L;
  double before = -INFINITY, before_half = 0, lengths = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double half = 0.5 * diameter[p.species[std::size_t(order[k])]];
    // kept at least the contact distance past the rod before (the sums'
    // rounding could leave it an ulp short)
    double x = offset + u[k] + lengths + half;
    while (x - before < before_half + half) x = std::nextafter(x, INFINITY);
    before = x, before_half = half, lengths += 2.0 * half;
    while (x >= L) x -= L;
    p.r[std::size_t(order[k])] = {x, 0.0, 0.0};
  }
}

}  // namespace

void place_random_mixture(Particles& p, const std::vector<double>& diameter, Geometry g, Random& rng,
                          InterruptFlag interrupt, const PlacementReport& report) {
  if (g.d() == 1) return place_rod_mixture(p, diameter, rng, interrupt, report);
  const std::size_t n = p.size();
  const double L = p.L, half = L / 2, top = std::nextafter(L, 0.0);
  const double widest = *std::max_element(diameter.begin(), diameter.end());
  CellGrid grid(L, widest, n, g);  // the scene checked that the box fits it
  const auto image = [&](double d) { return d > half ? d - L : (d < -half ? d + L : d); };
  const int lo[3] = {-1, -int(g.spans(1)), -int(g.spans(2))}, hi[3] = {1, int(g.spans(1)), int(g.spans(2))};
  // Largest first; within a species, by id.
  std::vector<std::int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::int32_t a, std::int32_t b) { return diameter[p.species[a]] > diameter[p.species[b]]; });
  std::int64_t placed = 0, failures = 0;
  double covered = 0;  // in unit particles
  for (std::int64_t trial = 0; std::size_t(placed) < n; ++trial) {
    if ((trial & 4095) == 0) {
      throw_if_interrupted(interrupt);
      if (report) report(placed);
    }
    const std::int32_t i = order[std::size_t(placed)];
    const double a = 0.5 * diameter[p.species[std::size_t(i)]];
    Vec3 x;
    for (int d = 0; d < 3; ++d) x[d] = g.spans(d) ? std::min(rng.uniform() * L, top) : 0.0;
    const int cell = grid.cell_of(x.x, x.y, x.z);
    bool free = true;
    for_each_neighbour_cell(grid.cells_per_side(), L, grid.coord(cell), lo, hi, [&](const NeighbourCell& nb) {
      for (int j = grid.first(nb.index); j >= 0 && free; j = grid.next(j)) {
        const Vec3& r = p.r[std::size_t(j)];
        const double dx = image(r.x - x.x), dy = image(r.y - x.y), dz = image(r.z - x.z);
        const double sigma = a + 0.5 * diameter[p.species[std::size_t(j)]];
        free = dx * dx + dy * dy + dz * dz >= sigma * sigma;
      }
    });
    if (!free) {
      if (++failures < kMaxFailuresInARow) continue;
      throw InputError("random placement of the mixture saturated at phi = " +
                       format_number(g.covered_fraction(covered, L)) + " (" + std::to_string(placed) + " of " +
                       std::to_string(n) + " placed); lower system.phi");
    }
    failures = 0;
    p.r[std::size_t(i)] = x;
    grid.insert(int(i), cell);
    covered += g.power(2.0 * a);
    ++placed;
  }
}

}  // namespace coolgas
