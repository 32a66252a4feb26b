// The cells within reach of an aggregate, on the aggregation engine's grid
// (aggregation_engine.h), whose cells are sized for typical aggregates
// rather than for the largest one.
//
// Two aggregates whose centres lie in cells o cells apart along an axis are
// at least (|o| - 1) w apart (w the cell width), so with contact distance σ
// they can touch only if |o| <= 1 + floor(σ / w) on every axis: their
// reach. Reach 1 is the 27 neighbours. The grid's cells are a hair wider than
// the width asked for (cell_grid.cc), and reaches are computed with the width
// asked for, which absorbs positions rounded at the last digit. A wide reach
// may wrap the box more than once (2 reach + 1 > n cells per side): each
// offset is then a distinct periodic image of the same cell, and every image
// is visited, since the one that touches first is not known in advance.
#pragma once
#include <cmath>
#include <vector>

#include "simulate/engine/cell_grid.h"

namespace coolgas {

inline int cell_reach(double sigma, double width) { return 1 + static_cast<int>(std::floor(sigma / width)); }

// Offset o from cell coordinate c along one axis: the wrapped coordinate and
// the shift (a multiple of L) that brings that cell's aggregates to offset o.
struct AxisStep {
  int cell;
  double shift;
};
inline AxisStep axis_step(int c, int o, int n, double L) {
  const int x = c + o;
  const int q = x >= 0 ? x / n : -((n - 1 - x) / n);  // floor(x / n)
  return {x - q * n, q * L};
}

// Calls f(cell coordinates, wrapped; shift) for every offset in
// [-reach, reach]² x [-reach_z, reach_z] around c of a grid of n³ cells in a
// box of side L (z slowest, x fastest); reach_z = 0 on the one layer of a 2D
// grid.
template <class F>
void for_each_cell_within(int n, double L, const CellCoord& c, int reach, int reach_z, F&& f) {
  std::vector<AxisStep> x(std::size_t(2 * reach + 1)), y(x.size());
  for (int o = -reach; o <= reach; ++o) {
    x[std::size_t(o + reach)] = axis_step(c.x, o, n, L);
    y[std::size_t(o + reach)] = axis_step(c.y, o, n, L);
  }
  for (int oz = -reach_z; oz <= reach_z; ++oz) {
    const AxisStep z = axis_step(c.z, oz, n, L);
    for (const AxisStep& sy : y)
      for (const AxisStep& sx : x) f(CellCoord{sx.cell, sy.cell, z.cell}, Vec3{sx.shift, sy.shift, z.shift});
  }
}

// Along one axis, a far cell `delta` cells from the centre cell (wrapped
// coordinates, |delta| < n) seen at every offset o ≡ delta (mod n) with
// |o| <= reach: calls f(o, shift), the shift bringing its aggregates there.
template <class F>
void for_each_image_offset(int delta, int n, double L, int reach, F&& f) {
  const int below = delta + reach;  // o = delta - q n >= -reach for q <= floor(below / n)
  int q = below >= 0 ? below / n : -((n - 1 - below) / n);
  for (int o = delta - q * n; o <= reach; o += n, --q) f(o, -q * L);
}

}  // namespace coolgas
