// Checks shared by the engines' restoring constructors: a checkpoint is
// read byte for byte and its hash only detects a torn file, so a crafted or
// damaged one with a consistent hash would otherwise be trusted, and an
// index out of range is a wild access, a NaN a run that never ends. Each
// check refuses through StateReader::fail (InputError naming the file).
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "simulate/engine/cell_grid.h"
#include "simulate/engine/engine_base.h"
#include "simulate/engine/motion.h"
#include "simulate/engine/state_archive.h"

namespace coolgas {

inline bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// L finite and positive, now finite and not negative, counters not negative
// and nested (below_delta <= collisions, stale <= events).
void check_scalars(const StateReader& in, const std::string& prefix, double L, double now, const EngineCounters& c);

// A particle's record: position and velocity finite (and its speed squared),
// its own time finite and in [0, now], and its motion since then shorter
// than the box side L (what moving it to now can wrap in a few steps).
void check_motion(const StateReader& in, const std::string& prefix, std::size_t i, const Motion& m, double now,
                  double L);

// A particle's position at its own time lies in its logical cell, to within
// half a cell (it was there at its last event; the margin is round-off's).
void check_in_cell(const StateReader& in, const std::string& prefix, std::size_t i, const Vec3& r,
                   const CellGrid& grid, int cell);

// The grid a checkpoint's heads belong to has `cells` cells (0 if the box
// is too small): checked before the grid is allocated.
void check_grid_size(const StateReader& in, const std::string& heads, std::int64_t cells);

}  // namespace coolgas
