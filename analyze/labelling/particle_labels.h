// Which cluster each particle belongs to, for callers that need the
// labelling itself rather than the masses (the Python module's
// label_clusters): the cluster of the cell holding its centre, numbered by
// rank in ClusterLabeller::ranked() (0 = the largest; ties by smallest cell).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "analyze/labelling/cluster_grid.h"
#include "analyze/labelling/cluster_labeller.h"

namespace coolgas {

// `labeller` has labelled `positions` (x0 y0 z0 x1 ...) on `grid`; `ranked`
// is its ranked(). One rank per particle.
std::vector<std::int32_t> particle_ranks(const ClusterGrid& grid, const ClusterLabeller& labeller,
                                         const std::vector<Cluster>& ranked, std::span<const double> positions);

}  // namespace coolgas
