// Random sequential addition (RSA) of unit spheres in the periodic box:
// each new centre uniform over the space still available (at distance >= 1
// from every centre placed so far). Plain trials while they mostly succeed,
// then the voxel method of Zhang & Torquato, PRE 88, 053312 (2013), which
// samples only voxels not yet known to be covered, so that the cost per
// sphere stays bounded up to saturation (phi = 0.384) instead of diverging.
//
// At the switch (a window of plain trials with under 2 % success, phi ~ 0.24)
// every cell is voxelized at once, two levels deep, keeping the voxels no
// single exclusion sphere covers (rsa_free_voxels.h); each sphere placed then
// removes the voxels it covers, and a failed trial refines its voxel. The
// memory the searches read is kept small (rsa_centre_grid.h): they are bound
// by memory latency. N = 1e6 at phi = 0.35 takes about 5 s and 218 bytes per
// particle (tests/bench/rsa_bench.cc).
#pragma once
#include <cstdint>
#include <functional>

#include "common/random.h"
#include "simulate/engine/particles.h"
#include "simulate/start/setup_interrupt.h"

namespace coolgas {

// Told how many spheres are placed so far, for a progress line: called where
// the interrupt flag is looked at, so it costs nothing per trial.
using PlacementReport = std::function<void(std::int64_t placed)>;

// Places p.r[0..N) (p.L set, p sized to N). Deterministic for a given rng
// state (the report changes nothing). Throws InputError if the packing
// saturates before N spheres, and SetupInterrupted once *interrupt is set
// (looked at every 4096 trials).
void place_random_sequential(Particles& p, std::int64_t N, Random& rng, InterruptFlag interrupt = nullptr,
                             const PlacementReport& report = {});

// Random sequential addition in a periodic box of side L until no room is
// left for another sphere; returns how many were placed (for tests of the
// saturation density).
std::int64_t saturate_random_sequential(double L, Random& rng);

}  // namespace coolgas
