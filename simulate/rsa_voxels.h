// Random sequential addition (RSA) of unit spheres in the periodic box:
// each new centre uniform over the space still available (at distance >= 1
// from every centre placed so far). Plain trials while they mostly succeed,
// then the voxel method of Zhang & Torquato, PRE 88, 053312 (2013), which
// samples only sub-cells not yet known to be covered, so that the cost per
// sphere stays bounded up to saturation (phi = 0.384) instead of diverging.
//
// Known limit: N = 1e6 at phi = 0.35 takes ~70 s and ~470 B per particle of
// voxel lists. Most voxels leave the lists only when a trial lands in them;
// most are covered by several spheres together but never by one. The next
// step is an index of voxels per cell, so that placing a sphere removes the
// voxels it covers at once, and voxels packed into 8 bytes.
#pragma once
#include <cstdint>

#include "simulate/particles.h"
#include "simulate/random.h"

namespace coolgas {

// Places p.r[0..N) (p.L set, p sized to N). Deterministic for a given rng
// state. Throws InputError if the packing saturates before N spheres.
void place_random_sequential(Particles& p, std::int64_t N, Random& rng);

}  // namespace coolgas
