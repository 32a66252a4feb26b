// A slow, plainly correct engine for tests (in the spirit of DynamO's
// ReferenceFEL): every particle moved to the current time at every event,
// every pair predicted with the minimum image convention, all predictions in
// one std::priority_queue, validity checked by collision counters. No cells,
// no calendar, no lazy positions: nothing clever to get wrong. O(N) per event.
#pragma once
#include <cstdint>
#include <vector>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/engine/engine.h"

namespace coolgas {

// Runs from time `now` until t_end or max_collisions, whichever comes first,
// returning every collision in order. The box must be wide enough for the
// minimum image convention (L > 2 diameters).
template <class Rule>
std::vector<CollisionRecord> reference_collisions(Particles p, const Rule& rule, double now, double t_end,
                                                  std::int64_t max_collisions);

// Ballistic aggregation the slow way: at each step every pair of present
// aggregates is predicted (σ = (d_i + d_j)/2; the minimum image, and any
// other image that could touch first, for aggregates up to L/2 wide), all move to the
// earliest contact, that pair merges (centre of mass, summed mass and volume,
// (area, length), momentum kept; the smaller id survives), and
// then, as long as the new aggregate overlaps any other, it merges with the
// smallest such id. Returns every merge as (kept, absorbed, time), up to
// t_end or max_merges. Disks (z = 0) need nothing else: the images across z
// are a box side away, beyond any contact.
std::vector<CollisionRecord> reference_merges(Particles p, AggregateState a, double now, double t_end,
                                              std::int64_t max_merges, Geometry g);

}  // namespace coolgas
