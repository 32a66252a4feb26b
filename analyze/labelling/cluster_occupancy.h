// Which cells of the cluster grid hold particle centres.
//
// Layout: cells are stored row by row (a row is the ncell cells of one
// (y, z) at increasing x), each row padded to whole 64-bit words so that rows
// can be compared word by word (cluster_runs.h, cluster_contacts.h). Occupancy is one
// bit per cell: cell (x, j, k) is bit b = x + 64*W*(j + ncell*k) of the grid,
// i.e. bit (b & 63) of word (b >> 6), with W words per row.
//
// The particles are sorted by z-plane on the way (a counting sort). They come
// in id order, which is spatially random, and touching 8e6 random places of a
// grid-sized array costs over 100 ms in cache and TLB misses; plane by plane,
// everything a plane needs stays in cache. The sorted list is kept: the
// labeller counts the particles of each run of cells from it, plane by plane
// while the plane is still in cache (the callback of build()).
#pragma once
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "analyze/labelling/cluster_grid.h"

namespace coolgas {

class CellOccupancy {
 public:
  // Fills the grid from centres x0 y0 z0 x1 ... (buffers are reused between
  // calls). Planes are filled in increasing z; plane_done(k) runs as soon as
  // plane k is complete, before plane k+1 is touched.
  void build(
      const ClusterGrid& grid, std::span<const double> positions,
      const std::function<void(int)>& plane_done = [](int) {});

  const ClusterGrid& grid() const { return grid_; }
  int words_per_row() const { return words_; }
  std::int64_t rows() const { return std::int64_t(grid_.rows_per_plane()) * grid_.planes(); }
  // Occupancy words of row r = j + ncell*k.
  const std::uint64_t* row(std::int64_t r) const { return bits_.data() + r * words_; }
  bool occupied(std::int64_t i, std::int64_t r) const { return (row(r)[i >> 6] >> (i & 63)) & 1u; }

  // The particles of plane k, each as the bit index b of its cell.
  std::span<const std::uint32_t> plane_particles(int k) const {
    return {by_plane_.data() + plane_start_[k], by_plane_.data() + plane_start_[k + 1]};
  }

 private:
  void sort_by_plane(std::span<const double> positions);

  ClusterGrid grid_{1.0, Geometry(3)};
  int words_ = 0;
  std::vector<std::uint64_t> bits_;
  // Counting-sort scratch: each particle's cell bit, then the same grouped by plane.
  std::vector<std::uint32_t> bit_, by_plane_;
  std::vector<std::int64_t> plane_start_;
};

}  // namespace coolgas
