// The pairs of particles in a periodic box that may lie within a reach of
// each other: the particles are sorted into cells at least `reach` wide (and
// not many more cells than particles: about the d-th root of their count
// per side), and each pair in the same or neighbouring cells is offered
// once, in O(n). The caller measures the pair's distance and decides; both
// overlap checks (coolgas-validate's, and the start's of a configuration
// from outside) share it.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "common/geometry.h"

namespace coolgas {

// `members` the particles to sort (indices into the caller's arrays),
// position(i) their coordinates (three doubles, inside [0, L); those past
// the dimension 0), f(i, j) called for each candidate pair. With fewer than
// three cells per side neighbouring cells are not distinct: every pair.
template <class Position, class F>
void for_each_close_pair(const std::vector<std::size_t>& members, Position position, double reach, double L,
                         Geometry g, F f) {
  const double per_side = std::ceil(g.root(double(members.size())));
  const int n = int(std::min({std::floor(L / reach), per_side + 1, 1e9}));
  if (n < 3) {
    for (std::size_t a = 0; a < members.size(); ++a)
      for (std::size_t b = a + 1; b < members.size(); ++b) f(members[a], members[b]);
    return;
  }
  const double w = L / n;
  const int ny = g.along(1, n), nz = g.along(2, n);
  auto coord = [&](std::size_t i, int k) {
    return std::clamp(int(std::floor(position(i)[k] / w)), 0, g.along(k, n) - 1);
  };
  auto cell_of = [&](int x, int y, int z) {
    return (std::size_t(z) * std::size_t(ny) + std::size_t(y)) * std::size_t(n) + std::size_t(x);
  };
  std::vector<std::size_t> start(std::size_t(n) * std::size_t(ny) * std::size_t(nz) + 1, 0), order(members.size());
  for (std::size_t i : members) ++start[cell_of(coord(i, 0), coord(i, 1), coord(i, 2)) + 1];
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i : members) order[fill[cell_of(coord(i, 0), coord(i, 1), coord(i, 2))]++] = i;
  for (std::size_t a = 0; a < order.size(); ++a) {
    const std::size_t i = order[a];
    const int cx = coord(i, 0), cy = coord(i, 1), cz = coord(i, 2);
    for (int o = 0; o < 27; ++o) {
      const int oy = o / 3 % 3 - 1, oz = o / 9 - 1;
      if ((ny == 1 && oy != 0) || (nz == 1 && oz != 0)) continue;  // one cell across: visited once
      const std::size_t c = cell_of((cx + o % 3 - 1 + n) % n, (cy + oy + ny) % ny, (cz + oz + nz) % nz);
      for (std::size_t b = start[c]; b < start[c + 1]; ++b)
        if (order[b] > i) f(i, order[b]);
    }
  }
}

}  // namespace coolgas
