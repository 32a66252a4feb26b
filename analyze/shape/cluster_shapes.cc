#include "analyze/shape/cluster_shapes.h"

#include <algorithm>
#include <cmath>

namespace coolgas {

std::vector<ClusterShape> ClusterShapes::of_particles(const ClusterGrid& grid, std::span<const double> positions) {
  labeller_.label(grid, positions);
  unwrapping_.build(grid, labeller_, positions);
  const auto& clusters = unwrapping_.clusters();
  sums_.assign(clusters.size(), GyrationSums{});
  const std::int64_t n = grid.per_side();
  const double w = grid.width(), L = grid.box();
  const std::size_t count = positions.size() / 3;
  for (std::size_t p = 0; p < count; ++p) {
    const double* r = positions.data() + 3 * p;
    const std::int32_t cell = grid.cell_of(r[0], r[1], r[2]);
    const CellImage& img = unwrapping_.image(cell);
    const std::size_t k = std::size_t(img.cluster);
    // Relative to the lower corner of the cluster's first cell, which is in image 0.
    const std::int64_t f = clusters[k].first_cell;
    sums_[k].add(r[0] + L * img.x - w * double(f % n), r[1] + L * img.y - w * double((f / n) % n),
                 r[2] + L * img.z - w * double(f / (n * n)));
  }
  std::vector<ClusterShape> out(clusters.size());
  for (std::size_t k = 0; k < clusters.size(); ++k) out[k] = {shape_of(sums_[k], grid.geometry()), unwrapping_.wraps(k)};
  return out;
}

std::vector<ClusterShape> aggregate_shapes(std::span<const double> mass, Geometry g) {
  std::vector<ClusterShape> out;
  out.reserve(mass.size());
  for (double m : mass) {
    ClusterShape c;
    c.shape.mass = std::llround(m);
    // A solid d-ball of diameter D: <x^2> = (D/2)^2 / (d + 2) along each of its axes
    // (D^2/20 for a sphere, D^2/16 for a disc, D^2/12 for a rod).
    const double D = g.diameter_of_mass(m), l = D * D / (4.0 * (g.d() + 2));
    for (int k = 0; k < 3; ++k) c.shape.lambda[std::size_t(k)] = g.spans(k) ? l : 0.0;
    c.shape.Rg = std::sqrt(g.d() * l);
    out.push_back(c);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const ClusterShape& a, const ClusterShape& b) { return a.shape.mass > b.shape.mass; });
  return out;
}

}  // namespace coolgas
