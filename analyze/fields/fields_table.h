// One frame's rows of the coolgas-fields tables: the series (one row a
// dump) and the spectrum (a block of shells a dump).
#pragma once
#include <string>
#include <vector>

#include "analyze/fields/cell_fields.h"
#include "analyze/fields/flow_split.h"
#include "common/tsv.h"

namespace coolgas {

const std::vector<std::string>& fields_columns(bool spectrum);

// The series row of a frame at time t: its energies and split.
std::vector<double> fields_row(double t, const CellFields& f, const FieldEnergies& e, const FlowSplit& s);
// The spectrum block of a frame at time t.
TableBlock spectrum_block(double t, const FlowSplit& s);

}  // namespace coolgas
