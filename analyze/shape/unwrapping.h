// Periodic unwrapping of the paper's clusters (analyze/labelling/) along
// their own connectivity: a breadth-first walk over each cluster's occupied
// cells, from its smallest cell, gives every cell the periodic image in
// which it joins the cells before it through shared faces. A particle's
// unwrapped position is then its position plus L times its cell's image, so
// a cluster cut by the box faces is whole again.
//
// A cluster that meets itself in another image (a face leads to a cell
// already reached in a different image) winds around the box: it percolates,
// it has no unwrapped shape, and it is flagged as wrapping.
// The labels (which cluster, its mass) are the labeller's; this walk only
// adds the images, and keeps each cell's cluster beside its image so that a
// particle finds both in one memory access. Memory: 8 bytes per cell.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "analyze/labelling/cluster_grid.h"
#include "analyze/labelling/cluster_labeller.h"

namespace coolgas {

struct CellImage {
  std::int8_t x = 0, y = 0, z = 0;  // periodic image, in box lengths
  std::uint8_t occupied = 0, reached = 0;
  std::int32_t cluster = -1;        // index in clusters()
};

class ClusterUnwrapping {
 public:
  // Walks every cluster of `labeller`, which labelled `positions` on `grid`,
  // in ranked() order.
  void build(const ClusterGrid& grid, const ClusterLabeller& labeller, std::span<const double> positions);

  const std::vector<Cluster>& clusters() const { return clusters_; }  // labeller.ranked()
  bool wraps(std::size_t cluster) const { return wraps_[cluster]; }
  const CellImage& image(std::int64_t cell) const { return image_[cell]; }

 private:
  void walk(const ClusterGrid& grid, std::size_t cluster);

  std::vector<Cluster> clusters_;
  std::vector<char> wraps_;
  std::vector<CellImage> image_;
  std::vector<std::int64_t> queue_;
};

}  // namespace coolgas
