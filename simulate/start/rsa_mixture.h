// The start of a mixture (the scene's [[species]]): spheres or disks of
// several diameters placed by random sequential addition, largest first,
// each new centre uniform over the box and kept if it touches no particle
// placed so far (plain trials over cells as wide as the largest particle);
// rods of several lengths placed exactly as equal ones are
// (rod_placement.h), in a random order along the ring.
//
// Plain trials saturate sooner than the voxel method of equal spheres
// (rsa_voxels.h); the scene keeps a mixture below phi = 0.30 in 3D and 0.40
// in 2D (scene.h, kMaxMixturePhi), where the largest particles, placed
// first into an empty box, are far from saturation and the small ones fill
// the gaps.
#pragma once
#include <cstdint>
#include <vector>

#include "common/geometry.h"
#include "common/random.h"
#include "simulate/engine/particles.h"
#include "simulate/start/rsa_voxels.h"
#include "simulate/start/setup_interrupt.h"

namespace coolgas {

// Places p.r[0..n) (p.L set, p.r and p.species sized to n; particle i of
// diameter[p.species[i]]) in dimension g. Deterministic for a given rng
// state. Throws InputError if no free place is found in a long run of
// trials (the packing is near saturation), and SetupInterrupted once
// *interrupt is set (looked at every 4096 trials, where `report` is told
// how many are placed).
void place_random_mixture(Particles& p, const std::vector<double>& diameter, Geometry g, Random& rng,
                          InterruptFlag interrupt = nullptr, const PlacementReport& report = {});

}  // namespace coolgas
