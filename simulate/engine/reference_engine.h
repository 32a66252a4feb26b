// A slow, plainly correct engine for tests (in the spirit of DynamO's
// ReferenceFEL): every particle moved to the current time at every event,
// every pair predicted with the minimum image convention, all predictions in
// one std::priority_queue, validity checked by collision counters. No cells,
// no calendar, no lazy positions: nothing clever to get wrong. O(N) per event.
#pragma once
#include <cstdint>
#include <vector>

#include "simulate/engine/engine.h"

namespace coolgas {

// Runs from time `now` until t_end or max_collisions, whichever comes first,
// returning every collision in order. The box must be wide enough for the
// minimum image convention (L > 2 diameters).
template <class Rule>
std::vector<CollisionRecord> reference_collisions(Particles p, const Rule& rule, double now, double t_end,
                                                  std::int64_t max_collisions);

}  // namespace coolgas
