// The initial state: N non-overlapping unit spheres placed at random (or on
// an FCC lattice), relaxed into an equilibrium fluid by a short elastic run
// (system.equilibrate), then given fresh Maxwellian velocities with zero total
// momentum and temperature exactly T0, so that the initial mean collision
// time is the time unit. Same scene and seed, same state, bit for bit.
#pragma once
#include <functional>
#include <string>

#include "simulate/engine/particles.h"
#include "simulate/run/scene.h"
#include "simulate/start/setup_interrupt.h"

namespace coolgas {

// What the set-up is doing, for a progress line: `line`, and whether it
// starts a phase (false: an update within one, shown when due).
using SetupReport = std::function<void(const std::string& line, bool phase)>;

// Throws InputError if the positions cannot be placed (random sequential
// addition saturating, a lattice too dense for the box), and
// SetupInterrupted within a fraction of a second of *interrupt being set.
Particles initial_state(const Scene& scene, InterruptFlag interrupt = nullptr, const SetupReport& report = {});

// The temperature of the initial state (per velocity component).
double initial_temperature(const Scene& scene);

}  // namespace coolgas
