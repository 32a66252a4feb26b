// Which cluster each particle belongs to, for callers that need the
// labelling itself rather than the masses (the Python module's
// label_clusters): the cluster of the cell holding its centre, numbered by
// rank in ClusterLabeller::ranked() (0 = the largest; ties by smallest cell);
// or, by contact, its own cluster, ranked the same way (ties by smallest particle).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "analyze/labelling/cluster_grid.h"
#include "analyze/labelling/cluster_labeller.h"
#include "analyze/labelling/contact_labeller.h"

namespace coolgas {

// `labeller` has labelled `positions` (x0 y0 z0 x1 ...) on `grid`; `ranked`
// is its ranked(). One rank per particle.
std::vector<std::int32_t> particle_ranks(const ClusterGrid& grid, const ClusterLabeller& labeller,
                                         const std::vector<Cluster>& ranked, std::span<const double> positions);

// Contact clusters ranked: the rank of each particle's cluster, and each
// cluster's mass and smallest particle index, largest first.
struct RankedContacts {
  std::vector<std::int32_t> rank;  // per particle
  std::vector<std::int64_t> mass, first_particle;  // per cluster, by rank
};
// `labeller` has labelled `n` particles.
RankedContacts contact_ranks(const ContactLabeller& labeller, std::size_t n);

}  // namespace coolgas
