// One dump's rows of the coolgas-clusters tables (data-schema/tsv-tables.md,
// "Shared table shapes"), from the cluster masses of a frame. The tool
// writes them; the Python module (analyze/python/) returns them.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "analyze/clusters/cluster_definition.h"
#include "analyze/clusters/mass_distribution.h"
#include "analyze/labelling/cluster_labeller.h"
#include "analyze/labelling/contact_labeller.h"
#include "common/tsv.h"
#include "common/geometry.h"

namespace coolgas {

enum class ClusterTable {
  kDistribution,  // one block per dump: t m dm N x y
  kScaled,        // one block per dump: t x y (the paper's Fig. 3)
  kSeries         // one row per dump: t M0 M1 M2 M_avg M_max largest_fraction
};

const std::vector<std::string>& cluster_columns(ClusterTable table);

// The labellers of both definitions, their buffers kept from frame to frame.
struct Labellers {
  ClusterLabeller cells;
  ContactLabeller contact;
};

// The masses of one frame into `hist` (cleared first): the clusters of the
// particles at `positions` (x0 y0 z0 x1 ...; z = 0 in 2D, y = z = 0 in 1D)
// in a box of side L in the geometry g by `definition` (the paper's unit
// cubes, squares or segments of the ring; or contacts, the cutoff checked
// against L by the caller), or, when `aggregate_mass` is not empty
// (ballistic aggregation), the aggregates themselves, each of its mass
// rounded to whole particles. `diameter` (a mixture's, one per particle;
// empty: unit particles) scales the contacts' bonds (contact_labeller.h).
void fill_cluster_masses(MassHistogram& hist, Labellers& labellers, const ClusterDefinition& definition, double L,
                         std::span<const double> positions, std::span<const double> aggregate_mass, Geometry g,
                         std::span<const double> diameter = {});

// The rows of one dump at time t in a box of side L in the geometry g: the
// densities are per L^d. The series has one row and no comment (it is not a
// block).
TableBlock cluster_block(ClusterTable table, double t, double L, const MassHistogram& hist, Geometry g);

}  // namespace coolgas
