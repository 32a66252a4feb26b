#include "simulate/initial_state.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "common/error.h"
#include "common/tsv.h"
#include "simulate/cell_grid.h"
#include "simulate/engine.h"
#include "simulate/enskog.h"
#include "simulate/random.h"

namespace coolgas {

namespace {

// Attempts per particle before random sequential addition gives up. At
// phi = 0.35 (near its jamming limit 0.384) it needs about 30 on average.
constexpr double kMaxAttemptsPerParticle = 2000;

bool overlaps_any(const Particles& p, const CellGrid& grid, const Vec3& x) {
  const CellCoord c = grid.coord(grid.cell_of(x.x, x.y, x.z));
  const int n = grid.cells_per_side();
  for (int oz = -1; oz <= 1; ++oz)
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        const CellCoord nb{(c.x + ox + n) % n, (c.y + oy + n) % n, (c.z + oz + n) % n};
        for (int j = grid.first(grid.index(nb)); j >= 0; j = grid.next(j)) {
          Vec3 d{p.r[j].x - x.x, p.r[j].y - x.y, p.r[j].z - x.z};
          for (int k = 0; k < 3; ++k) d[k] -= p.L * std::round(d[k] / p.L);
          if (dot(d, d) < 1.0) return true;
        }
      }
  return false;
}

// Random sequential addition: draw a uniform point, keep it if it overlaps
// no sphere placed so far; the cell grid makes each check O(1).
void place_random(Particles& p, std::int64_t N, Random& rng) {
  CellGrid grid(p.L, 1.0, std::size_t(N));
  const double budget = kMaxAttemptsPerParticle * double(N);
  double attempts = 0;
  for (std::int64_t i = 0; i < N; ++i) {
    Vec3 x;
    do {
      if (++attempts > budget) {
        const double reached = double(i) * M_PI / (6.0 * p.L * p.L * p.L);
        throw InputError("random sequential addition stalled at phi = " + format_number(reached) +
                         " (placed " + std::to_string(i) + " of " + std::to_string(N) +
                         " spheres); use system.init = \"fcc\" or a lower phi");
      }
      x = {rng.uniform() * p.L, rng.uniform() * p.L, rng.uniform() * p.L};
      for (int d = 0; d < 3; ++d) x[d] = std::min(x[d], std::nextafter(p.L, 0.0));
    } while (overlaps_any(p, grid, x));
    p.r[i] = x;
    grid.insert(int(i), grid.cell_of(x.x, x.y, x.z));
  }
}

// N of the 4k³ sites of the smallest FCC lattice holding N, chosen at random.
void place_fcc(Particles& p, std::int64_t N, Random& rng) {
  const auto k = static_cast<std::int64_t>(std::ceil(std::cbrt(double(N) / 4.0) - 1e-12));
  const std::int64_t sites = 4 * k * k * k;
  const double a = p.L / double(k);
  if (a / std::sqrt(2.0) < 1.0 + 1e-9)
    throw InputError("system.phi = " + format_number(double(N) * M_PI / (6 * p.L * p.L * p.L)) +
                     " is too dense for an FCC lattice of " + std::to_string(sites) +
                     " sites in this box (neighbour distance " + format_number(a / std::sqrt(2.0)) +
                     " < 1); lower phi or choose N = 4k^3");
  std::vector<std::int64_t> idx(static_cast<std::size_t>(sites));
  std::iota(idx.begin(), idx.end(), 0);
  for (std::int64_t i = 0; i < N; ++i) std::swap(idx[i], idx[i + std::int64_t(rng.below(std::uint64_t(sites - i)))]);
  std::sort(idx.begin(), idx.begin() + N);
  static const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  for (std::int64_t i = 0; i < N; ++i) {
    const std::int64_t s = idx[i], cell = s / 4, b = s % 4;
    const std::int64_t cx = cell % k, cy = (cell / k) % k, cz = cell / (k * k);
    p.r[i] = {(double(cx) + basis[b][0] + 0.25) * a, (double(cy) + basis[b][1] + 0.25) * a,
              (double(cz) + basis[b][2] + 0.25) * a};
  }
}

// Maxwellian velocities, total momentum removed, rescaled to T0 exactly.
void draw_velocities(Particles& p, double T0, Random& rng) {
  Vec3 mean;
  for (auto& v : p.v) {
    v = {rng.normal(), rng.normal(), rng.normal()};
    for (int d = 0; d < 3; ++d) mean[d] += v[d];
  }
  const double n = double(p.size());
  double sum2 = 0;
  for (auto& v : p.v) {
    for (int d = 0; d < 3; ++d) v[d] -= mean[d] / n;
    sum2 += dot(v, v);
  }
  const double scale = std::sqrt(T0 * 3.0 * n / sum2);
  for (auto& v : p.v)
    for (int d = 0; d < 3; ++d) v[d] *= scale;
}

}  // namespace

double initial_temperature(const Scene& s) {
  return unit_time_temperature(double(s.N) / (s.L * s.L * s.L), s.phi);
}

Particles initial_state(const Scene& s) {
  Particles p;
  p.L = s.L;
  p.resize(std::size_t(s.N));
  Random rng(std::uint64_t(s.seed));
  if (s.init == InitialPositions::kRandom) place_random(p, s.N, rng);
  else place_fcc(p, s.N, rng);
  const double T0 = initial_temperature(s);
  draw_velocities(p, T0, rng);
  if (s.equilibrate > 0) {
    Engine<ElasticRule> melt(std::move(p), ElasticRule{}, 0.0);
    melt.run_until(s.equilibrate, std::numeric_limits<std::int64_t>::max(), nullptr);
    melt.synchronize();
    p = melt.snapshot();
    std::fill(p.t.begin(), p.t.end(), 0.0);
    std::fill(p.image.begin(), p.image.end(), Image{0, 0, 0});
    draw_velocities(p, T0, rng);
  }
  return p;
}

}  // namespace coolgas
