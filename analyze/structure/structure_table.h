// One frame's rows of the coolgas-structure tables (data-schema/tsv-tables.md,
// "coolgas-structure"), from its positions, velocities and weights. The tool
// writes them; the Python module (analyze/python/) returns them.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "analyze/structure/frame_structure.h"
#include "analyze/structure/radial_distribution.h"
#include "analyze/structure/tool.h"
#include "common/tsv.h"

namespace coolgas {

const std::vector<std::string>& structure_columns(StructureTable table);

// InputError unless the grid is 0 or even in [8, 1024], the peak fraction in
// (0, 1) and the direct shells in [0, 8] (the tool's options, named as such).
void check_structure_options(int grid, double peak_fraction, int direct_shells);

// The grid points per side for box side L: `grid`, or when 0 the even number
// nearest below L (spacing about sigma), at most 1024. InputError if that is
// below 8, or if the grid's arrays in geometry `g` (structure_grid_bytes)
// need more than `memory_bytes` (the callers': usable_memory_bytes(),
// common/memory.h): the line names --grid, the bytes and the largest grid
// that fits, before anything is allocated.
int structure_grid_points(int grid, double L, Geometry g, double memory_bytes);
// The bytes of a FrameStructure of n points per side: the density grid
// (n + 2 reals per row, FFTW's padding) and the power spectrum of the
// correlations (n/2 + 1 per row).
double structure_grid_bytes(int n, Geometry g);

// The rows of one frame at time t in a box of side L, on `fs` (its grid
// chosen by structure_grid_points): the spectrum's block (its comment the
// check against the exact sum over `direct_shells` shells), the series' one
// row (no comment) or the correlation's block. Positions and velocities are
// x0 y0 z0 x1 ...; `weights` one per point (aggregates: their masses), empty
// for unit weights; velocities are used by the series and correlation only.
TableBlock structure_block(StructureTable table, FrameStructure& fs, double t, double L,
                           std::span<const double> positions, std::span<const double> velocities,
                           std::span<const double> weights, double peak_fraction, int direct_shells);

// InputError unless r_max is 0 or positive and finite, bins_per_sigma in
// [1, 1000] and contact_bins in [2, bins_per_sigma] (--r-max,
// --bins-per-sigma, --contact-bins).
void check_rdf_options(double r_max, int bins_per_sigma, int contact_bins);
// g(r)'s range for a box of side L: `r_max`, or when 0 min(5, L/2). InputError
// if it exceeds L/2 (the minimum image), leaves no room for the contact fit
// (sigma + contact_bins / bins_per_sigma), or makes more than 10^7 bins.
double rdf_range(double r_max, double L, int bins_per_sigma, int contact_bins);

// The rows of one frame's g(r) (kRdf: a block, its comment the contact value)
// or its contact value (kRdfSeries: one row) at time t in a box of side L, on
// `pairs` (cleared first; its range checked against L by rdf_range).
// Positions as for structure_block; every particle of diameter sigma.
TableBlock rdf_block(StructureTable table, PairDistances& pairs, double t, double L,
                     std::span<const double> positions, int contact_bins, Geometry g);

}  // namespace coolgas
