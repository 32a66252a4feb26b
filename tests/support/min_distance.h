// The overlap oracle: distances over ALL pairs (periodic, minimum image),
// O(N^2) on purpose. It shares no code with the engines (no cell grid), so a
// bug in the grid or the neighbour walk cannot hide from it; use it at the
// small N where N^2 pairs take well under a second.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "simulate/engine/particles.h"

namespace coolgas::test {

// The largest overlap (d_i + d_j)/2 - |r_i - r_j| over all pairs of positions
// wrapped into [0, L) (negative: no pair touches). diameter empty: unit
// spheres; a diameter of 0 marks an absent particle (aggregation's empty slots).
inline double largest_overlap(const std::vector<Vec3>& r, double L, const std::vector<double>& diameter = {}) {
  const double half = L / 2;
  auto image = [L, half](double d) { return d > half ? d - L : (d < -half ? d + L : d); };
  double worst = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double di = diameter.empty() ? 1.0 : diameter[i];
    if (di == 0) continue;
    for (std::size_t j = i + 1; j < r.size(); ++j) {
      const double dj = diameter.empty() ? 1.0 : diameter[j];
      if (dj == 0) continue;
      const double dx = image(r[j].x - r[i].x), dy = image(r[j].y - r[i].y), dz = image(r[j].z - r[i].z);
      worst = std::max(worst, 0.5 * (di + dj) - std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  }
  return worst;
}

// The smallest centre distance over all pairs of unit spheres.
inline double min_pair_distance(const Particles& p) { return 1.0 - largest_overlap(p.r, p.L); }

}  // namespace coolgas::test
