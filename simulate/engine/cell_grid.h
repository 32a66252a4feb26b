// The cell grid: the periodic box cut into ncell³ cubic cells at least one
// diameter wide (ncell² square ones for disks in 2D: one layer, z = 0; a
// row of ncell for rods on a ring in 1D: y = z = 0), each
// holding a doubly linked list of the particles whose centres it contains.
// Two spheres can only touch if their cells are neighbours (the 27 cells
// around, periodic; 9 in 2D, 3 in 1D), so collision searches look only there. A particle's cell is logical: it changes only at a cell-crossing
// event, never by reading the position, so round-off cannot lose a particle.
// The forward links of the lists may live inside the caller's particle
// records (bind_next_links), so that walking a cell touches one cache line
// per particle. The list heads are stored in blocks of 4 x 2 x 2 cells, one
// cache line each (slot()): the 27 cells around one then span 6 lines on
// average instead of 9 rows of 3, and the 9 beyond a face 3.3 instead of 5.3
// (in 2D, blocks of 4 x 4 cells; in 1D, runs of 16).
// Cells keep their plain index (z n + y) n + x everywhere else, checkpoints
// included.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "common/geometry.h"
#include "simulate/engine/particles.h"
#include "simulate/engine/state_archive.h"

namespace coolgas {

struct CellCoord {
  int x, y, z;
};

class CellGrid {
 public:
  // Cells of side >= min_width (the largest diameter) in a box of side L, for
  // n particles, in a cube, a square (one layer of cells) or on a ring (one
  // row of cells).
  CellGrid(double L, double min_width, std::size_t n, Geometry g);
  CellGrid() = default;  // no cells: a placeholder to assign to, or to free a grid

  int cells_per_side() const { return n_; }
  int layers() const { return layers_; }  // cells along z: n in 3D, 1 in 2D and 1D
  // Cells along y: n in 3D and 2D, 1 in 1D (one term of slot() per row; no
  // member of its own, so the 3D engine's layout is what it was).
  int rows() const { return static_cast<int>(slot_y_.size()); }
  double width() const { return w_; }
  std::int64_t cell_count() const { return std::int64_t(n_) * rows() * layers_; }

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
  // Where a cell's list head is stored: a sum of one term per axis.
  int slot(const CellCoord& c) const { return slot_x_[c.x] + slot_y_[c.y] + slot_z_[c.z]; }
  int first_in_slot(int slot) const { return head_[slot]; }
  int first(int cell) const { return head_[std::size_t(slot(coord(cell)))]; }
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

  // The lists (heads, links, each particle's cell) under names starting with
  // `prefix`; load() expects a grid constructed with the same geometry (and
  // links bound the same way; bound links are the caller's to save).
  void save(StateWriter& out, const std::string& prefix) const;
  // load() checks every index and list (a crafted or damaged file is
  // refused through in.fail(), naming it); bound links must be loaded first.
  void load(const StateReader& in, const std::string& prefix);
  // The cells a grid of side L with cells >= min_width wide has (0 if the box
  // is too small): what a checkpoint's heads must number, known before the
  // grid is allocated.
  static std::int64_t cells_for(double L, double min_width, Geometry g);

 private:
  int n_ = 0;
  int layers_ = 0;
  double w_ = 0;
  double inv_n_ = 0;  // 1 / n_
  std::vector<std::int32_t> head_;  // first particle of each cell, -1 if empty, at slot(cell)
  std::vector<std::int32_t> slot_x_, slot_y_, slot_z_;  // slot()'s terms, one per coordinate
  std::vector<std::int32_t> prev_, cell_;
  std::vector<std::int32_t> own_next_;  // forward links, unless bound to the caller's records
  std::int32_t* next_ = nullptr;
  std::size_t stride_ = 1;
  std::int32_t& link(int p) { return next_[std::size_t(p) * stride_]; }
  std::int32_t& head_of(int cell) { return head_[std::size_t(slot(coord(cell)))]; }
  void check_lists(const StateReader& in, const std::string& prefix) const;
};

// One cell of a neighbour walk.
struct NeighbourCell {
  int index;          // (z n + y) n + x
  CellCoord cell;     // its coordinates, wrapped into 0..n-1
  CellCoord offset;   // from the centre cell, each -1, 0 or 1
  Vec3 shift;         // what brings its particles next to the centre cell's: ±L where the walk wraps, else 0
};

// The periodic walk over neighbouring cells, which every caller shares (the
// engines, random sequential addition's centre grid and free voxels): calls
// f(NeighbourCell) for the cells around c at offsets o[d] in [lo[d], hi[d]]
// (each within -1..1; z slowest, x fastest) of a grid of n³ cells in a box
// of side L (L only sets the shifts). The engine's partner search has a
// faster copy for interior cells (neighbour_slots below), tested against it;
// the centre grid's overlap test (rsa_centre_grid.h) walks nearest cells
// first instead, since it stops at the first hit.
template <class F>
void for_each_neighbour_cell(int n, double L, const CellCoord& c, const int* lo, const int* hi, F&& f) {
  auto wrap = [n, L](int x, double& shift) {
    shift = x < 0 ? -L : (x >= n ? L : 0.0);
    return x < 0 ? x + n : (x >= n ? x - n : x);
  };
  for (int oz = lo[2]; oz <= hi[2]; ++oz)
    for (int oy = lo[1]; oy <= hi[1]; ++oy)
      for (int ox = lo[0]; ox <= hi[0]; ++ox) {
        NeighbourCell nb;
        nb.offset = {ox, oy, oz};
        nb.cell = {wrap(c.x + ox, nb.shift.x), wrap(c.y + oy, nb.shift.y), wrap(c.z + oz, nb.shift.z)};
        nb.index = (nb.cell.z * n + nb.cell.y) * n + nb.cell.x;
        f(static_cast<const NeighbourCell&>(nb));
      }
}

// All 27 cells around c.
template <class F>
void for_each_neighbour_cell(int n, double L, const CellCoord& c, F&& f) {
  static constexpr int kLo[3] = {-1, -1, -1}, kHi[3] = {1, 1, 1};
  for_each_neighbour_cell(n, L, c, kLo, kHi, f);
}

// The same walk, specialised for the engine's partner search in dimension D
// (in 2D the offsets along z are 0 and the one layer never wraps; in 1D
// those along y too, and only x wraps): writes the
// cells' head slots (CellGrid::slot) to `slots` and returns how many. An
// interior cell (~90 % of them) needs no shifts, and `shifts` is left
// untouched (wraps = false); otherwise shifts[k] holds the shift of the k-th
// cell (wraps = true).
template <int D>
inline int neighbour_slots(const CellGrid& grid, double L, const CellCoord& c, const int* lo, const int* hi, int* slots,
                    double (*shifts)[3], bool& wraps) {
  const int n = grid.cells_per_side();
  int k = 0;
  if constexpr (D == 3) wraps = !(c.x > 0 && c.y > 0 && c.z > 0 && c.x < n - 1 && c.y < n - 1 && c.z < n - 1);
  else if constexpr (D == 2) wraps = !(c.x > 0 && c.y > 0 && c.x < n - 1 && c.y < n - 1);
  else wraps = !(c.x > 0 && c.x < n - 1);
  if (!wraps) {
    for (int oz = lo[2]; oz <= hi[2]; ++oz)
      for (int oy = lo[1]; oy <= hi[1]; ++oy)
        for (int ox = lo[0]; ox <= hi[0]; ++ox, ++k) slots[k] = grid.slot({c.x + ox, c.y + oy, c.z + oz});
    return k;
  }
  for_each_neighbour_cell(n, L, c, lo, hi, [&](const NeighbourCell& nb) {
    slots[k] = grid.slot(nb.cell);
    shifts[k][0] = nb.shift.x, shifts[k][1] = nb.shift.y, shifts[k][2] = nb.shift.z;
    ++k;
  });
  return k;
}

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
// the 27 neighbours of a cell are 27 distinct cells (3 in 1D).
std::string check_box_fits_grid(double L, double min_width);

}  // namespace coolgas
