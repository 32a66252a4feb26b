// The centres placed so far by random sequential addition, filed by cell of
// a grid of cells at least one diameter wide, so that every centre closer
// than one diameter to a point lies in the 27 cells around the point's cell.
//
// The search around a trial point is bound by memory latency, so it reads as
// little as it can: one bit per cell says whether the cell holds a centre
// (the bits stay in cache), and a cell holds its first centre in its own
// 16-byte slot, the offset from the cell's corner in single precision and
// the centre's id; further centres of the cell (a few per cent of the cells)
// are chained, flagged by a second bit. Offsets make the periodic images free
// (a neighbour across the box is one cell away). A distance that single
// precision cannot settle (within 4e-5 of a diameter, squared) is settled
// by the caller on the exact positions, so every answer is exactly that of
// the test in double precision.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "simulate/engine/cell_grid.h"
#include "simulate/engine/particles.h"

namespace coolgas {

class CentreGrid {
 public:
  // Cells of side L / n >= min_width >= one diameter (a hair more, so that
  // round-off in a position never hides a touching pair two cells apart),
  // and at least 3 per side where one-diameter cells allow it. Wider cells
  // (a dilute gas: about one centre per cell) keep the grid's memory near
  // the centres' own instead of L^3 cells; every answer stays the same.
  explicit CentreGrid(double L, double min_width = 1.0);

  int cells_per_side() const { return n_; }
  double width() const { return w_; }
  std::size_t cell_count() const { return first_.size(); }
  // The cell holding a position in [0, L) (clamped, so L - tiny lands inside).
  int cell_of(const Vec3& x) const { return index(axis(x.x), axis(x.y), axis(x.z)); }
  Vec3 corner(std::size_t cell) const {
    const std::size_t n = std::size_t(n_);
    return {double(cell % n) * w_, double(cell / n % n) * w_, double(cell / (n * n)) * w_};
  }
  int wrap(int k) const { return k < 0 ? k + n_ : (k >= n_ ? k - n_ : k); }

  void insert(const Vec3& r, std::int32_t id);
  // The coordinates of x's cell and x's offset from the cell's corner.
  void locate(const Vec3& x, int cell[3], Vec3& offset) const {
    for (int d = 0; d < 3; ++d) {
      cell[d] = axis(x[d]);
      offset[d] = x[d] - cell[d] * w_;
    }
  }

  // Whether a centre lies nearer than one diameter to x: exact(id) decides
  // for the centres that single precision cannot settle.
  template <class Exact>
  bool any_within_one(const Vec3& x, Exact&& exact) const;

  // Asks the memory for the slot of the cell holding x.
  void prefetch(const Vec3& x) const { __builtin_prefetch(&first_[std::size_t(cell_of(x))]); }

  // Asks the memory for the slots a gather around `cell` reads.
  void prefetch_near(std::size_t cell) const {
    const int cx = int(cell % std::size_t(n_)), cy = int(cell / std::size_t(n_) % std::size_t(n_)),
              cz = int(cell / (std::size_t(n_) * std::size_t(n_)));
    // Each row's cells x-1 and x+1 only: its middle cell lies between them in
    // memory (16-byte slots), on one of the two cache lines they bring.
    for_each_neighbour_cell(n_, 0.0, {cx, cy, cz}, [&](const NeighbourCell& nb) {
      if (nb.offset.x != 0) __builtin_prefetch(&first_[std::size_t(nb.index)]);
    });
  }

  // Calls f(cx, cy, cz, offset) for every centre, cell by cell: the
  // coordinates of its cell and its offset from the cell's corner (to single
  // precision).
  template <class F>
  void for_each_centre(F&& f) const;

  // Calls f(centre, id) with every centre in the 27 cells around `cell`,
  // relative to the cell's corner (to single precision: ~1e-7).
  template <class F>
  void for_each_near(std::size_t cell, F&& f) const;

 private:
  struct Slot {
    float x, y, z;  // offset from the cell's corner
    std::int32_t id;
  };
  struct Link {
    Slot slot;
    std::int32_t next;
  };
  int axis(double u) const { return std::clamp(int(std::floor(u / w_)), 0, n_ - 1); }
  int index(int x, int y, int z) const { return (z * n_ + y) * n_ + x; }
  static bool bit(const std::vector<std::uint64_t>& bits, std::size_t c) { return bits[c >> 6] >> (c & 63) & 1; }
  static void set(std::vector<std::uint64_t>& bits, std::size_t c) { bits[c >> 6] |= std::uint64_t(1) << (c & 63); }
  // Calls f(slot) for each centre of an occupied cell until it returns true.
  template <class F>
  bool any_in(std::size_t c, F&& f) const;

  // Offsets (0..2 per axis, 1 = the cell itself) by the number of axes that
  // differ: a rejected trial usually meets its obstacle in the first few.
  static constexpr std::array<std::array<std::uint8_t, 3>, 27> kNearestFirst = [] {
    std::array<std::array<std::uint8_t, 3>, 27> o{};
    std::size_t k = 0;
    for (int differing = 0; differing <= 3; ++differing)
      for (std::uint8_t z = 0; z < 3; ++z)
        for (std::uint8_t y = 0; y < 3; ++y)
          for (std::uint8_t x = 0; x < 3; ++x)
            if ((x != 1) + (y != 1) + (z != 1) == differing) o[k++] = {x, y, z};
    return o;
  }();
  // Squared distances farther than this from 1, times the cell width, are
  // settled in single precision (its round-off grows with the offsets, which
  // are below 3 widths: under 7e-6 for cells one diameter wide).
  static constexpr float kUnsure = 4e-5f;

  int n_;
  double w_;
  float wf_, unsure_;
  std::vector<std::uint64_t> occupied_;  // a bit per cell: it holds a centre
  std::vector<std::uint64_t> chained_;   // a bit per cell: it holds more than one
  std::vector<Slot> first_;              // each cell's first centre
  std::vector<std::int32_t> chain_;      // each cell's further centres in more_, -1 if none
  std::vector<Link> more_;
};

inline CentreGrid::CentreGrid(double L, double min_width)
    : n_(std::max(std::min(int(std::floor(L / (1.0 + 1e-9))), 3),
                  int(std::floor(L / (std::max(1.0, min_width) * (1.0 + 1e-9)))))),
      w_(L / n_),
      wf_(float(w_)),
      unsure_(kUnsure * float(w_)) {
  const std::size_t cells = std::size_t(n_) * std::size_t(n_) * std::size_t(n_);
  occupied_.assign(cells / 64 + 1, 0);
  chained_.assign(cells / 64 + 1, 0);
  first_.resize(cells);
  chain_.assign(cells, -1);
}

inline void CentreGrid::insert(const Vec3& r, std::int32_t id) {
  const int ax = axis(r.x), ay = axis(r.y), az = axis(r.z);
  const std::size_t c = std::size_t(index(ax, ay, az));
  const Slot s{float(r.x - ax * w_), float(r.y - ay * w_), float(r.z - az * w_), id};
  if (!bit(occupied_, c)) {
    set(occupied_, c);
    first_[c] = s;
    return;
  }
  set(chained_, c);
  more_.push_back({s, chain_[c]});
  chain_[c] = std::int32_t(more_.size() - 1);
}

template <class F>
bool CentreGrid::any_in(std::size_t c, F&& f) const {
  if (f(first_[c])) return true;
  if (bit(chained_, c))
    for (std::int32_t j = chain_[c]; j >= 0; j = more_[std::size_t(j)].next)
      if (f(more_[std::size_t(j)].slot)) return true;
  return false;
}

template <class Exact>
bool CentreGrid::any_within_one(const Vec3& x, Exact&& exact) const {
  const int ax = axis(x.x), ay = axis(x.y), az = axis(x.z);
  // x relative to the corner of the cell below-left-front of its own, so
  // that a centre in neighbour (i, j, k) of that corner is at (i, j, k) w + its offset.
  const float px = float(x.x - ax * w_) + wf_, py = float(x.y - ay * w_) + wf_, pz = float(x.z - az * w_) + wf_;
  // Not the shared walk (cell_grid.h), which visits cells in a fixed order:
  // this test stops at the first centre it meets, so it goes nearest first.
  const int xs[3] = {wrap(ax - 1), ax, wrap(ax + 1)};
  const int ys[3] = {wrap(ay - 1), ay, wrap(ay + 1)};
  const int zs[3] = {wrap(az - 1), az, wrap(az + 1)};
  for (const auto& o : kNearestFirst) {
    const std::size_t c = std::size_t(index(xs[o[0]], ys[o[1]], zs[o[2]]));
    if (!bit(occupied_, c)) continue;
    const float ox = float(o[0]) * wf_, oy = float(o[1]) * wf_, oz = float(o[2]) * wf_;
    const bool hit = any_in(c, [&](const Slot& s) {
      const float dx = s.x + ox - px, dy = s.y + oy - py, dz = s.z + oz - pz;
      const float d2 = dx * dx + dy * dy + dz * dz;
      if (d2 < 1.0f - unsure_) return true;
      return d2 <= 1.0f + unsure_ && exact(s.id);
    });
    if (hit) return true;
  }
  return false;
}

template <class F>
void CentreGrid::for_each_near(std::size_t cell, F&& f) const {
  const int cx = int(cell % std::size_t(n_)), cy = int(cell / std::size_t(n_) % std::size_t(n_)),
            cz = int(cell / (std::size_t(n_) * std::size_t(n_)));
  // The occupied cells first (their bits are in cache), then their slots in
  // one sweep without branches, so that the memory fetches them together.
  std::size_t cells[27];
  std::uint8_t offset[27];
  int k = 0;
  for_each_neighbour_cell(n_, 0.0, {cx, cy, cz}, [&](const NeighbourCell& nb) {
    const auto c = std::size_t(nb.index);
    cells[k] = c;
    offset[k] = std::uint8_t(((nb.offset.z + 1) * 3 + nb.offset.y + 1) * 3 + nb.offset.x + 1);
    k += bit(occupied_, c);
  });
  Slot slots[27];
  for (int j = 0; j < k; ++j) slots[j] = first_[cells[j]];
  for (int j = 0; j < k; ++j) {
    const int o = offset[j];
    const double ox = (o % 3 - 1) * w_, oy = (o / 3 % 3 - 1) * w_, oz = (o / 9 - 1) * w_;
    const auto at = [&](const Slot& s) { f(Vec3{ox + s.x, oy + s.y, oz + s.z}, s.id); };
    at(slots[j]);
    if (bit(chained_, cells[j]))
      for (std::int32_t m = chain_[cells[j]]; m >= 0; m = more_[std::size_t(m)].next) at(more_[std::size_t(m)].slot);
  }
}

template <class F>
void CentreGrid::for_each_centre(F&& f) const {
  for (int z = 0; z < n_; ++z)
    for (int y = 0; y < n_; ++y)
      for (int x = 0; x < n_; ++x) {
        const std::size_t c = std::size_t(index(x, y, z));
        if (!bit(occupied_, c)) continue;
        any_in(c, [&](const Slot& s) {
          f(x, y, z, Vec3{s.x, s.y, s.z});
          return false;
        });
      }
}

}  // namespace coolgas
