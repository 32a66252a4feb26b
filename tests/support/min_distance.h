// Distances between neighbouring particles (periodic), via a cell grid.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include "simulate/engine/cell_grid.h"
#include "simulate/engine/particles.h"

namespace coolgas::test {

// Calls f(i, j, distance) once for every pair i < j of the particles filed
// in `grid` whose cells are neighbours, in a periodic box of side L; pos(i)
// is particle i's position.
template <class Pos, class F>
void for_each_near_pair(const CellGrid& grid, std::size_t count, double L, Pos&& pos, F&& f) {
  const int n = grid.cells_per_side();
  for (std::size_t i = 0; i < count; ++i) {
    if (grid.cell(int(i)) < 0) continue;  // not filed
    const CellCoord c = grid.coord(grid.cell(int(i)));
    const Vec3 ri = pos(i);
    for (int oz = -1; oz <= 1; ++oz)
      for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox) {
          const CellCoord nb{(c.x + ox + n) % n, (c.y + oy + n) % n, (c.z + oz + n) % n};
          for (int j = grid.first(grid.index(nb)); j >= 0; j = grid.next(j)) {
            if (j <= int(i)) continue;
            const Vec3 rj = pos(std::size_t(j));
            Vec3 d{rj.x - ri.x, rj.y - ri.y, rj.z - ri.z};
            for (int k = 0; k < 3; ++k) d[k] -= L * std::round(d[k] / L);
            f(i, std::size_t(j), std::sqrt(dot(d, d)));
          }
        }
  }
}

// The smallest centre distance over all pairs.
inline double min_pair_distance(const Particles& p) {
  CellGrid grid(p.L, 1.0, p.size());
  for (std::size_t i = 0; i < p.size(); ++i) grid.insert(int(i), grid.cell_of(p.r[i].x, p.r[i].y, p.r[i].z));
  double best = std::numeric_limits<double>::infinity();
  for_each_near_pair(grid, p.size(), p.L, [&](std::size_t i) { return p.r[i]; },
                     [&](std::size_t, std::size_t, double r) { best = std::min(best, r); });
  return best;
}

}  // namespace coolgas::test
