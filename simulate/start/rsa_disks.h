// Random sequential addition of unit disks in the periodic square (the 2D
// start, system.dimension = 2): each new centre uniform over the square,
// kept if it lies at distance >= 1 from every centre placed so far. Plain
// trials only: below phi = 0.45 (scene.h, kMaxRandomPhi2D; saturation is at
// 0.547) they succeed often enough that no voxel method is needed.
#pragma once
#include <cstdint>

#include "common/random.h"
#include "simulate/engine/particles.h"
#include "simulate/start/rsa_voxels.h"
#include "simulate/start/setup_interrupt.h"

namespace coolgas {

// Places p.r[0..N) with z = 0 (p.L set, p.r sized to N). Deterministic for a
// given rng state. Throws InputError if no free place is found in a long run
// of trials (the packing is near saturation), and SetupInterrupted once
// *interrupt is set (looked at every 4096 trials, where `report` is told how
// many disks are placed).
void place_random_disks(Particles& p, std::int64_t N, Random& rng, InterruptFlag interrupt = nullptr,
                        const PlacementReport& report = {});

}  // namespace coolgas
