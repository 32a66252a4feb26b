// One frame's rows of the coolgas-fields tables: the series (one row a
// dump), the spectrum (a block of shells a dump) and the slab (a block of
// cells a dump).
#pragma once
#include <string>
#include <vector>

#include "analyze/fields/cell_fields.h"
#include "analyze/fields/flow_split.h"
#include "common/tsv.h"

namespace coolgas {

enum class FieldsTable { kSeries, kSpectrum, kSlab };

const std::vector<std::string>& fields_columns(FieldsTable table);

// The series row of a frame at time t: its energies and split.
std::vector<double> fields_row(double t, const CellFields& f, const FieldEnergies& e, const FlowSplit& s);
// The spectrum block of a frame at time t.
TableBlock spectrum_block(double t, const FlowSplit& s);
// The slab block of a frame at time t: the cells of the middle plane
// (iz = n/2; 2D: the plane), density and the vorticity normal to the plane.
TableBlock slab_block(double t, const CellFields& f);

}  // namespace coolgas
