// The cell grid: the periodic box cut into ncell³ cubic cells at least one
// diameter wide, each holding a doubly linked list of the particles whose
// centres it contains. Two spheres can only touch if their cells are
// neighbours (the 27 cells around, periodic), so collision searches look only
// there. A particle's cell is logical: it changes only at a cell-crossing
// event, never by reading the position, so round-off cannot lose a particle.
// The forward links of the lists may live inside the caller's particle
// records (bind_next_links), so that walking a cell touches one cache line
// per particle.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "simulate/engine/particles.h"

namespace coolgas {

struct CellCoord {
  int x, y, z;
};

class CellGrid {
 public:
  // Cells of side >= min_width (the largest diameter) in a box of side L, for n particles.
  CellGrid(double L, double min_width, std::size_t n);
  CellGrid() = default;  // no cells: a placeholder to assign to, or to free a grid

  int cells_per_side() const { return n_; }
  double width() const { return w_; }
  std::int64_t cell_count() const { return std::int64_t(n_) * n_ * n_; }

  int index(const CellCoord& c) const { return (c.z * n_ + c.y) * n_ + c.x; }
  // Integer division by n done in floating point (a multiplication, not an
  // integer division of ~40 cycles; the search calls this on every event):
  // (cell + 1/2) / n lies at least 1/(2n) away from an integer, far beyond
  // the rounding of the product for any grid that fits an int.
  CellCoord coord(int cell) const { return coord_in(cell, n_, inv_n_); }
  static CellCoord coord_in(int cell, int n, double inv_n) {
    const int zy = static_cast<int>((cell + 0.5) * inv_n);
    const int z = static_cast<int>((zy + 0.5) * inv_n);
    return {cell - zy * n, zy - z * n, z};
  }
  // The cell containing a wrapped position (clamped, so x = L - tiny lands inside).
  int cell_of(double x, double y, double z) const;

  int cell(int particle) const { return cell_[particle]; }
  void prefetch_cell(int particle) const { __builtin_prefetch(&cell_[std::size_t(particle)]); }
  int first(int cell) const { return head_[cell]; }
  int next(int particle) const { return next_[std::size_t(particle) * stride_]; }
  // Keeps the forward links at base[i * stride] instead of in the grid.
  void bind_next_links(std::int32_t* base, std::size_t stride) {
    next_ = base;
    stride_ = stride;
    std::vector<std::int32_t>().swap(own_next_);  // free it, not just empty it
  }

  void insert(int particle, int cell);
  void remove(int particle);
  void move(int particle, int cell) {
    remove(particle);
    insert(particle, cell);
  }
  void clear();

 private:
  int n_ = 0;
  double w_ = 0;
  double inv_n_ = 0;  // 1 / n_
  std::vector<std::int32_t> head_;  // first particle of each cell, -1 if empty
  std::vector<std::int32_t> prev_, cell_;
  std::vector<std::int32_t> own_next_;  // forward links, unless bound to the caller's records
  std::int32_t* next_ = nullptr;
  std::size_t stride_ = 1;
  std::int32_t& link(int p) { return next_[std::size_t(p) * stride_]; }
};

// When a particle at r (at the current time) moving with v first leaves its
// cell, and through which face: 2 d + 1 for the upper face along axis d, 2 d
// for the lower one. time is never negative (a particle a hair past a face by
// round-off crosses at once) and infinite for a particle at rest.
struct CellExit {
  double time;
  int face;
};
CellExit first_cell_exit(const CellGrid& grid, int cell, const Vec3& r, const Vec3& v);

// The cell a particle enters when it crosses `face` (as numbered by
// CellExit) of `cell`. Leaving the box through a face wraps it: r moves by
// ∓L along that axis and the image count by ±1, so r stays in the box.
int cell_across_face(const CellGrid& grid, int cell, int face, double L, Vec3& r, Image& image);

// The smallest box the grid supports: three cells of the given width, so that
// the 27 neighbours of a cell are 27 distinct cells.
std::string check_box_fits_grid(double L, double min_width);

}  // namespace coolgas
