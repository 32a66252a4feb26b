// One frame's fields as a VTK ImageData file (.vti: VTK's XML format, raw
// appended little-endian binary), which ParaView, VisIt and VTK read as
// they are. Chosen over XDMF + HDF5 because one self-contained file per dump
// opens in every VTK-based viewer with no second file to keep beside it.
// Cell data, one value per cell of the n^d grid (origin 0, spacing L/n):
//   density [sigma^-d]: particles per cell volume;
//   velocity [sigma omega0]: the cell's flow velocity, momentum / mass (0 when empty);
//   temperature [m sigma^2 omega0^2]: 2 (K_c - |p_c|^2 / 2 M_c) / (d (n_c - 1)) for n_c >= 2, else 0;
//   vorticity [omega0]: curl of the velocity by central differences over
//     neighbouring cells (3D: 3 components; 2D: the z component; 1D: 0).
#pragma once
#include <string>

#include "analyze/fields/cell_fields.h"

namespace coolgas {

// Writes `path` (through a temporary file renamed over it, so a reader never
// sees half a file); InputError naming the path when it cannot be written.
void write_vti(const std::string& path, const CellFields& f);

}  // namespace coolgas
