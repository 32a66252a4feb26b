// The pairs of particles in a periodic box that may lie within a reach of
// each other: the particles are sorted into cells at least `reach` wide (and
// not many more cells than particles: about the d-th root of their count
// per side), and each pair in the same or neighbouring cells is offered
// once, in O(n). The caller measures the pair's distance and decides; both
// overlap checks (coolgas-validate's, and the start's of a configuration
// from outside) share it.
//
// The analysis of large frames (g(r), contact clusters) uses PairsWithin
// below instead: it measures the distances itself, over a copy of the
// coordinates sorted by cell, and visits each pair of cells once.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
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

// Every pair of points closer than `reach` by the periodic minimum image
// (reach <= L/2), each once, for analyses of large frames (8e6 points): the
// points are sorted into cells about reach/2 wide (no more cells than about
// n^(1/d) + 1 a side), their coordinates copied in that order, and each
// point is measured against the points after it in its own row of cells
// within reach, and against every point of the rows of cells ahead of its
// own (a half shell), rows and cells beyond reach of the point left out. A
// row's cells are contiguous in the copy, so the inner loop reads memory in
// order. In 3D, cells reach/2 wide put 5^3 (r/2)^3 = 15.6 r^3 around a point,
// cells reach wide 27 r^3 (the sphere: 4.19 r^3).
//
// The squared distance is summed as every caller of for_each_close_pair
// sums it, |x_j - x_i| over the minimum image in x, y, z order (|a - b| is
// |b - a| exactly), so a distance is the same to the last bit.
class PairsWithin {
 public:
  // positions x0 y0 z0 x1 ... inside [0, L) (the coordinates past the
  // dimension 0), 0 < reach <= L/2.
  PairsWithin(std::span<const double> positions, double reach, double L, Geometry g);

  std::size_t size() const { return index_.size(); }
  // The caller's index of sorted point a.
  std::size_t index(std::size_t a) const { return index_[a]; }

  // f(a, b, r2) for each pair of sorted points a != b closer than reach, r2
  // their squared distance. Pairs come cell by cell, so a and b are
  // neighbours in memory as well as in space.
  template <class F>
  void for_each(F f) const;

 private:
  template <class F>
  void measure(std::size_t a, std::size_t from, std::size_t to, F& f) const;

  // Cells and rows are skipped only beyond reach by this factor: rounding
  // never skips a pair whose distance would be measured within reach.
  static constexpr double kSafe = 1 + 1e-9;
  double L_, half_, reach_, reach2_, w_ = 0;
  int n_[3] = {1, 1, 1}, m_[3] = {0, 0, 0};  // cells per side, cells within reach
  bool all_pairs_ = false;                   // too few cells: every pair
  std::vector<double> x_, y_, z_;            // coordinates in cell order
  std::vector<std::uint32_t> index_;         // caller's index by sorted point
  std::vector<std::uint32_t> start_;         // first sorted point of each cell, and the end
};

template <class F>
void PairsWithin::measure(std::size_t a, std::size_t from, std::size_t to, F& f) const {
  const double xa = x_[a], ya = y_[a], za = z_[a];
  // In blocks: the distances first, the points within reach noted without a
  // branch (a quarter of them in a half shell; a branch on each mispredicted
  // often), then f on those.
  constexpr std::size_t kBlock = 64;
  std::uint32_t hit[kBlock];
  double d2[kBlock];
  for (std::size_t b0 = from; b0 < to; b0 += kBlock) {
    const std::size_t nb = std::min(kBlock, to - b0);
    std::size_t k = 0;
    for (std::size_t i = 0; i < nb; ++i) {
      const std::size_t b = b0 + i;
      double dx = std::abs(x_[b] - xa), dy = std::abs(y_[b] - ya), dz = std::abs(z_[b] - za);
      dx = dx > half_ ? L_ - dx : dx;
      dy = dy > half_ ? L_ - dy : dy;
      dz = dz > half_ ? L_ - dz : dz;
      const double r2 = dx * dx + dy * dy + dz * dz;
      hit[k] = std::uint32_t(i);
      d2[k] = r2;
      k += r2 < reach2_;
    }
    for (std::size_t j = 0; j < k; ++j) f(a, b0 + hit[j], d2[j]);
  }
}

template <class F>
void PairsWithin::for_each(F f) const {
  const std::size_t count = index_.size();
  if (all_pairs_) {
    for (std::size_t a = 0; a < count; ++a) measure(a, a + 1, count, f);
    return;
  }
  const int nx = n_[0], ny = n_[1], nz = n_[2], mx = m_[0], my = m_[1], mz = m_[2];
  const double w = w_, reach2 = reach2_ * kSafe;
  auto row = [&](int y, int z) { return (std::size_t(z) * std::size_t(ny) + std::size_t(y)) * std::size_t(nx); };
  // The points of cells x0 ... x1 (unwrapped, periodic) of a row: one or two ranges.
  auto cells = [&](std::size_t r, int x0, int x1, std::size_t a) {
    if (x1 < x0) return;
    const int first = (x0 % nx + nx) % nx, span = x1 - x0 + 1, run = std::min(span, nx - first);
    measure(a, start_[r + std::size_t(first)], start_[r + std::size_t(first + run)], f);
    if (run < span) measure(a, start_[r], start_[r + std::size_t(span - run)], f);
  };
  // How far a coordinate lies outside cell c (unwrapped): a lower bound on
  // the distance to any point of it (other images are farther than reach,
  // as 2m + 1 cells fit in the box).
  auto gap = [w](double v, int c) { return std::max({0.0, c * w - v, v - (c + 1) * w}); };
  for (int cz = 0; cz < nz; ++cz)
    for (int cy = 0; cy < ny; ++cy) {
      const std::size_t home = row(cy, cz);
      for (int cx = 0; cx < nx; ++cx)
        for (std::size_t a = start_[home + std::size_t(cx)]; a < start_[home + std::size_t(cx) + 1]; ++a) {
          const double xa = x_[a], ya = y_[a], za = z_[a];
          // the cells of a row a point can reach over a half-width h
          auto last_x = [&](double h) { return std::min(cx + mx, int(std::floor((xa + h) / w))); };
          auto first_x = [&](double h) { return std::max(cx - mx, int(std::floor((xa - h) / w))); };
          // its own row: the points after it in its cell and the next cells within reach
          measure(a, a + 1, start_[home + std::size_t(cx) + 1], f);
          cells(home, cx + 1, last_x(reach_), a);
          // the rows ahead, (oy, oz) with oz > 0, or oz = 0 and oy > 0, where they are within reach
          for (int oz = 0; oz <= mz; ++oz) {
            const double gz = nz > 1 ? gap(za, cz + oz) : 0.0;
            for (int oy = oz > 0 ? -my : 1; oy <= my; ++oy) {
              const double gy = gap(ya, cy + oy), g2 = gy * gy + gz * gz;
              if (g2 >= reach2) continue;
              const double h = std::sqrt(reach2 - g2) * kSafe;
              cells(row((cy + oy + ny) % ny, (cz + oz) % nz), first_x(h), last_x(h), a);
            }
          }
        }
    }
}

}  // namespace coolgas
