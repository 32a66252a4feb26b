// coolgas-fields: the coarse-grained density, flow and temperature fields of
// the dumps of a trajectory, the flow's energy against the thermal one, and
// its split into longitudinal and transverse (vortical) parts
// (data-schema/tsv-tables.md, "coolgas-fields").
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "common/geometry.h"

namespace coolgas {

struct FieldsOptions {
  std::string input;            // trajectory file
  double cell = 4;              // cell side wanted [sigma]; the grid takes the even n nearest below L / cell
  bool spectrum = false;        // blocks of E_L(k), E_T(k) instead of one row per dump
  bool slab = false;            // blocks of the middle plane's cells instead (2D and 3D)
  std::string vti;              // directory for one .vti file per dump; empty: none
  std::vector<double> times;    // dumps nearest these times; empty = all dumps
  bool exact_time = false;
};

// Writes the table for opt to out (and the .vti files). InputError on bad
// input; nothing is written to out unless every dump was read.
void run_fields(const FieldsOptions& opt, std::ostream& out);

// The cells per side for box side L and cell side `cell`: the even number
// nearest below L / cell. InputError (naming --cell, before anything is
// allocated) unless the cell is at least one diameter, the count is at
// least 4, and the arrays of a frame's fields (kFieldBytesPerCell each) fit
// in `memory_bytes` (the caller's usable_memory_bytes(), common/memory.h).
int field_cells(double L, double cell, Geometry g, double memory_bytes);
// The cells' sums, the FFT grid, the transforms of d components and the
// .vti arrays: about 19 doubles a cell.
inline constexpr double kFieldBytesPerCell = 152;

}  // namespace coolgas
