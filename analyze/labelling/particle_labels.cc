#include "analyze/labelling/particle_labels.h"

#include <algorithm>
#include <numeric>

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

RankedContacts contact_ranks(const ContactLabeller& labeller, std::size_t n) {
  // The clusters in the labeller's order (by smallest particle): their roots and masses.
  std::vector<std::int64_t> roots, mass;
  for (std::size_t i = 0; i < n; ++i)
    if (labeller.root_of(i) == std::int32_t(i)) roots.push_back(std::int64_t(i));
  labeller.for_each_mass([&](std::int64_t m) { mass.push_back(m); });
  std::vector<std::size_t> order(roots.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  // stable: equal masses keep the order of their smallest particles
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return mass[a] > mass[b]; });
  RankedContacts out;
  std::vector<std::int32_t> rank_of_root(n, -1);
  for (std::size_t r = 0; r < order.size(); ++r) {
    rank_of_root[std::size_t(roots[order[r]])] = std::int32_t(r);
    out.mass.push_back(mass[order[r]]);
    out.first_particle.push_back(roots[order[r]]);
  }
  out.rank.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.rank[i] = rank_of_root[std::size_t(labeller.root_of(i))];
  return out;
}

}  // namespace coolgas
