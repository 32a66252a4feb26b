// The initial state: N non-overlapping unit spheres placed at random (or on
// an FCC lattice; disks at random in 2D, with z = 0; rods in their exact
// equilibrium configuration in 1D, rod_placement.h), relaxed into an equilibrium fluid by a short elastic run
// (system.equilibrate), then given fresh Maxwellian velocities with zero total
// momentum and temperature exactly T0, so that the initial mean collision
// time is the time unit. Same scene and seed, same state, bit for bit.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "common/random.h"
#include "simulate/engine/particles.h"
#include "simulate/scene/scene.h"
#include "simulate/start/setup_interrupt.h"

namespace coolgas {

// What the set-up is doing, for a progress line: `line`, and whether it
// starts a phase (false: an update within one, shown when due).
using SetupReport = std::function<void(const std::string& line, bool phase)>;

// Throws InputError if the positions cannot be placed (random sequential
// addition saturating, a lattice too dense for the box), and
// SetupInterrupted within a fraction of a second of *interrupt being set.
Particles initial_state(const Scene& scene, InterruptFlag interrupt = nullptr, const SetupReport& report = {});

// The temperature of the initial state (per velocity component): system.T0
// once a start from a file has set it, else the Enskog value of the time unit.
double initial_temperature(const Scene& scene);

// The kinetic energy per particle at t = 0, (d/2) T0: the E0 of the
// progress line's E/E0.
double initial_energy(const Scene& scene);

// Maxwellian velocities at temperature T0 (per component: m <v_x^2> = T0 in
// every dimension), total momentum removed and rescaled to T0 exactly;
// `mass` null for unit masses. In 2D only x and y are drawn, v_z is 0; in 1D
// only x.
void draw_velocities(Particles& p, double T0, Random& rng, const std::vector<double>* mass, Geometry g);

// Rough particles' spins at temperature T0 (per rotational axis: I <w_k^2> =
// T0, I = inertia a² m), rescaled to T0 exactly. A rough start draws them
// last, from the same generator, so its positions and velocities are those
// of the smooth start of the same seed. In 2D only w_z is drawn.
void draw_spins(Particles& p, double T0, double inertia, Random& rng, Geometry g);

}  // namespace coolgas
