// One frame's rows of the coolgas-shape tables (data-schema/tsv-tables.md,
// "coolgas-shape"), from its positions (gas) or its aggregates' masses
// (ballistic aggregation). The tool writes them; the Python module
// (analyze/python/) returns them.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "analyze/shape/cluster_shapes.h"
#include "analyze/shape/mass_radius.h"
#include "analyze/shape/tool.h"
#include "common/tsv.h"

namespace coolgas {

// The table's columns; a 2D table (dimension 2) has no lambda3 and no
// prolateness, a 1D table no lambda2, lambda3, asphericity or prolateness.
std::vector<std::string> shape_columns(ShapeTable table, Geometry g);

// InputError unless bins_per_decade >= 1 and min_mass >= 1 (the tool's options).
void check_shape_options(int bins_per_decade, std::int64_t min_mass);

// The rows of one frame at time t: the mass-radius block or the clusters'
// block (of at least min_mass particles), each with the d_f summary as its
// comment, or the series' one row (no comment).
TableBlock shape_block(ShapeTable table, double t, const std::vector<ClusterShape>& shapes, const MassRadius& mr,
                       std::int64_t min_mass, Geometry g);

}  // namespace coolgas
