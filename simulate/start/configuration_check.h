// Checks a configuration that did not come from our own start (a resumed
// file, a user's frame) before an engine runs on it: an engine trusts its
// state, so a NaN, a position outside the box or an overlap would make it
// hang, crash or run on nonsense.
#pragma once
#include <cstdint>
#include <string>

#include "common/geometry.h"
#include "simulate/engine/aggregation_engine.h"
#include "simulate/engine/particles.h"

namespace coolgas {

// Pairs closer than contact * (1 - kOverlapTolerance) overlap. Dumps are
// taken at synchronised states, where touching pairs sit at contact to
// within round-off (the engine keeps pairs to 1 - 1e-10 of contact).
inline constexpr double kOverlapTolerance = 1e-9;

// Throws InputError (one line, naming `source`) at the first problem:
// - N < 2 or >= 2^31, or arrays of different lengths;
// - L not finite, too small for the cell grid (3 cells of the largest
//   diameter) or too large (more than 2^31 cells of one diameter);
// - a position not finite or outside [0, L), a velocity not finite or so
//   large that its kinetic energy overflows;
// - two spheres closer than their contact distance (the pair and the
//   distance are named), found in O(N) with a cell grid.
// `aggregates` (ballistic aggregation; null for unit spheres) gives each
// slot's diameter; empty slots (id -1) are skipped. In 2D and 1D, disks
// (z = 0) or rods (y = z = 0), whose grids have one layer or one row of
// cells (so a ring may be up to 2^31 long).
// `diameters` (a mixture's; null otherwise) gives each particle's diameter,
// any finite one above 0.
void check_configuration(const Particles& p, const AggregateState* aggregates, const std::string& source,
                         Geometry g, const std::vector<double>* diameters = nullptr);

}  // namespace coolgas
