// The start of hard rods on a ring (system.dimension = 1): an exact draw
// from the equilibrium hard-rod configuration, not random sequential
// addition. In equilibrium the N gaps between neighbouring unit rods on a
// ring of length L are uniform on the simplex {gaps >= 0, sum = L - N}, which
// is what the spacings of N uniform points on a ring of length L - N are: so
// the points are drawn, sorted, the i-th shifted by i (one rod length per rod
// before it) and the whole turned by a random offset. It works at any
// phi < 1, and needs no equilibration.
#pragma once
#include <cstdint>

#include "common/random.h"
#include "simulate/engine/particles.h"
#include "simulate/start/rsa_voxels.h"
#include "simulate/start/setup_interrupt.h"

namespace coolgas {

// Places p.r[0..N) with y = z = 0 (p.L set, N < L, p.r sized to N), in order
// along the ring from a random point. Deterministic for a given rng state.
// Throws SetupInterrupted once *interrupt is set (looked at every 2^16 rods,
// where `report` is told how many are drawn).
void place_rods(Particles& p, std::int64_t N, Random& rng, InterruptFlag interrupt = nullptr,
                const PlacementReport& report = {});

}  // namespace coolgas
