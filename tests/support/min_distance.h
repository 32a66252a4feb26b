// The smallest centre distance over all pairs (periodic), via a cell grid.
#pragma once
#include <cmath>
#include <limits>

#include "simulate/cell_grid.h"
#include "simulate/particles.h"

namespace coolgas::test {

inline double min_pair_distance(const Particles& p) {
  CellGrid grid(p.L, 1.0, p.size());
  for (std::size_t i = 0; i < p.size(); ++i) grid.insert(int(i), grid.cell_of(p.r[i].x, p.r[i].y, p.r[i].z));
  const int n = grid.cells_per_side();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const CellCoord c = grid.coord(grid.cell(int(i)));
    for (int oz = -1; oz <= 1; ++oz)
      for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox) {
          const CellCoord nb{(c.x + ox + n) % n, (c.y + oy + n) % n, (c.z + oz + n) % n};
          for (int j = grid.first(grid.index(nb)); j >= 0; j = grid.next(j)) {
            if (j <= int(i)) continue;
            Vec3 d{p.r[j].x - p.r[i].x, p.r[j].y - p.r[i].y, p.r[j].z - p.r[i].z};
            for (int k = 0; k < 3; ++k) d[k] -= p.L * std::round(d[k] / p.L);
            best = std::min(best, std::sqrt(dot(d, d)));
          }
        }
  }
  return best;
}

}  // namespace coolgas::test
