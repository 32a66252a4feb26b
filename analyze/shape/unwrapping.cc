#include "analyze/shape/unwrapping.h"

#include <algorithm>

namespace coolgas {

void ClusterUnwrapping::build(const ClusterGrid& grid, const ClusterLabeller& labeller,
                              std::span<const double> positions) {
  clusters_ = labeller.ranked();
  wraps_.assign(clusters_.size(), 0);
  image_.assign(std::size_t(grid.cells()), CellImage{});
  // Occupancy from the particles (the cells the labeller saw), so that the
  // walk tests a neighbour with one byte instead of a labeller query.
  for (std::size_t p = 0; p + 2 < positions.size(); p += 3)
    image_[grid.cell_of(positions[p], positions[p + 1], positions[p + 2])].occupied = 1;
  for (std::size_t i = 0; i < clusters_.size(); ++i) walk(grid, i);
}

// Breadth-first from the cluster's smallest cell, in image 0. Every cell
// reached through a face belongs to the same cluster, so the walk needs no
// labels; it gives each cell the cluster's index.
void ClusterUnwrapping::walk(const ClusterGrid& grid, std::size_t cluster) {
  const std::int64_t n = grid.per_side();
  queue_.clear();
  queue_.push_back(clusters_[cluster].first_cell);
  image_[queue_[0]].reached = 1;
  image_[queue_[0]].cluster = std::int32_t(cluster);
  for (std::size_t head = 0; head < queue_.size(); ++head) {
    const std::int64_t c = queue_[head];
    const CellImage here = image_[c];
    const std::int64_t at[3] = {c % n, (c / n) % n, c / (n * n)};
    // 2D: one plane, no z neighbours; 1D: one row. (The min states the
    // bound of `at` for the static analyzer: grid dimensions are 1 to 3.)
    for (int axis = 0; axis < std::min(grid.dimension(), 3); ++axis)
      for (int step : {-1, 1}) {
        std::int64_t to[3] = {at[0], at[1], at[2]};
        int shift = 0;  // image change on crossing the face at 0 or n
        to[axis] += step;
        if (to[axis] < 0) to[axis] += n, shift = -1;
        if (to[axis] >= n) to[axis] -= n, shift = 1;
        const std::int64_t nb = to[0] + n * (to[1] + n * to[2]);
        if (!image_[nb].occupied) continue;
        CellImage want = here;
        std::int8_t* w = axis == 0 ? &want.x : (axis == 1 ? &want.y : &want.z);
        const int moved = *w + shift;
        if (moved < -127 || moved > 127) {  // more than 127 boxes long: treat as winding
          wraps_[cluster] = 1;
          continue;
        }
        *w = std::int8_t(moved);
        CellImage& there = image_[nb];
        if (!there.reached) {
          want.reached = 1;
          want.cluster = std::int32_t(cluster);
          there = want;
          queue_.push_back(nb);
        } else if (there.x != want.x || there.y != want.y || there.z != want.z) {
          wraps_[cluster] = 1;
        }
      }
  }
}

}  // namespace coolgas
