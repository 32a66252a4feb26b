// Random sequential addition (RSA) of unit spheres in the periodic box:
// each new centre uniform over the space still available (at distance >= 1
// from every centre placed so far). Plain trials while they mostly succeed,
// then the voxel method of Zhang & Torquato, PRE 88, 053312 (2013), which
// samples only sub-cells not yet known to be covered, so that the cost per
// sphere stays bounded up to saturation (phi = 0.384) instead of diverging.
#pragma once
#include <cstdint>

#include "simulate/particles.h"
#include "simulate/random.h"

namespace coolgas {

// Places p.r[0..N) (p.L set, p sized to N). Deterministic for a given rng
// state. Throws InputError if the packing saturates before N spheres.
void place_random_sequential(Particles& p, std::int64_t N, Random& rng);

}  // namespace coolgas
