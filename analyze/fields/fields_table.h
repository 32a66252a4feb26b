// One frame's rows of the coolgas-fields tables: the series (one row a
// dump), the spectrum (a block of shells a dump) and the slab (a block of
// cells a dump).
#pragma once
#include <span>
#include <string>
#include <vector>

#include "analyze/fields/cell_fields.h"
#include "analyze/fields/flow_split.h"
#include "common/tsv.h"

namespace coolgas {

enum class FieldsTable { kSeries, kSpectrum, kSlab };

const std::vector<std::string>& fields_columns(FieldsTable table);

// One frame's block of `table` at time t in a box of side L, on `grid` (n
// cells per side, field_cells() of tool.h): what coolgas-fields writes for
// that dump (the series: a block of one row). Positions and velocities are
// x0 y0 z0 x1 ...; masses one per particle, empty for unit masses.
TableBlock fields_block(FieldsTable table, FourierGrid& grid, double t, double L, std::span<const double> positions,
                        std::span<const double> velocities, std::span<const double> masses);
// The same from the frame's cells (cell_fields on grid's n and geometry).
TableBlock fields_block(FieldsTable table, FourierGrid& grid, double t, const CellFields& f);

// The series row of a frame at time t: its energies and split.
std::vector<double> fields_row(double t, const CellFields& f, const FieldEnergies& e, const FlowSplit& s);
// The spectrum block of a frame at time t.
TableBlock spectrum_block(double t, const FlowSplit& s);
// The slab block of a frame at time t: the cells of the middle plane
// (iz = n/2; 2D: the plane), density and the vorticity normal to the plane.
TableBlock slab_block(double t, const CellFields& f);

}  // namespace coolgas
