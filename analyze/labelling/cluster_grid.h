// The paper's cluster grid: the periodic box of side L cut into cubic cells
// of side about one particle diameter (in 2D, square cells: the same grid
// with a single plane, k = 0, every disk's z being 0; in 1D, unit segments
// of the ring: a single row, j = k = 0, neighbours left and right).
//
// The paper uses cells of side exactly σ = 1, which tiles the box only when L
// is an integer. We use ncell = floor(L) cells per side of width
// w = L/ncell, so 1 <= w < 2 and w - 1 < 1/floor(L) (w = 1.0003 for the
// paper's L = 272.07). Cell (i, j, k) has the flat index
// i + ncell*(j + ncell*k): x runs fastest ("raster order").
//
// Which cells are occupied: cluster_occupancy.h; finding neighbouring occupied
// cells: cluster_contacts.h; using them (the disjoint-set union): cluster_labeller.h.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/geometry.h"

namespace coolgas {

class ClusterGrid {
 public:
  // Grid for a periodic box of side L in the geometry g (InputError unless
  // 1 <= L < 1251 in 3D, L < 40001 in 2D, L < 2^31 - 64 in 1D: the
  // labeller's links are 32-bit).
  ClusterGrid(double L, Geometry g);

  int per_side() const { return n_; }
  int dimension() const { return geo_.d(); }
  Geometry geometry() const { return geo_; }
  int planes() const { return geo_.along(2, n_); }          // along z
  int rows_per_plane() const { return geo_.along(1, n_); }  // along y
  double width() const { return width_; }
  double box() const { return L_; }
  std::int64_t cells() const { return std::int64_t(n_) * rows_per_plane() * planes(); }

  // Cell of one coordinate: floor(x / w) clamped to [0, ncell-1], so positions
  // a round-off outside [0, L) still land in the boundary cell. Computed as
  // x * (1/w) without branches (a division per coordinate would cost more than
  // the whole labelling); it differs from floor(x / w) only within an ulp of a
  // cell edge. NaN goes to cell 0 (the frame reader rejects NaN anyway).
  int cell_1d(double x) const {
    double s = x * inv_width_;
    s = s > 0 ? s : 0;
    s = s < last_ ? s : last_;
    return static_cast<int>(s);
  }
  std::int32_t cell_of(double x, double y, double z) const { return cell_1d(x) + n_ * (cell_1d(y) + n_ * cell_1d(z)); }

 private:
  double L_;
  Geometry geo_;
  int n_;
  double width_, inv_width_, last_;
};

// The grid of dump `dump` of the trajectory `path` (box side L): as
// The grid's cells and their neighbours, as provenance states them:
// "floor(L)^3 cubic cells of side L/floor(L); face neighbours; periodic".
std::string cluster_cells_text(Geometry g);

// ClusterGrid(L, g), with the InputError naming the file and the dump.
ClusterGrid cluster_grid_of_dump(double L, const std::string& path, std::size_t dump, Geometry g);

}  // namespace coolgas
