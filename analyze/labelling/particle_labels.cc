#include "analyze/labelling/particle_labels.h"

#include <algorithm>

namespace coolgas {

std::vector<std::int32_t> particle_ranks(const ClusterGrid& grid, const ClusterLabeller& labeller,
                                         const std::vector<Cluster>& ranked, std::span<const double> positions) {
  // Cluster ids are root runs: small non-negative integers, so a plain table maps them to ranks.
  std::int32_t max_id = -1;
  for (const Cluster& c : ranked) max_id = std::max(max_id, c.id);
  std::vector<std::int32_t> rank_of(std::size_t(max_id + 1), -1);
  for (std::size_t r = 0; r < ranked.size(); ++r) rank_of[std::size_t(ranked[r].id)] = std::int32_t(r);
  const std::size_t n = positions.size() / 3;
  std::vector<std::int32_t> out(n);
  for (std::size_t p = 0; p < n; ++p)
    out[p] = rank_of[std::size_t(labeller.cluster_of(grid.cell_of(positions[3 * p], positions[3 * p + 1], positions[3 * p + 2])))];
  return out;
}

}  // namespace coolgas
