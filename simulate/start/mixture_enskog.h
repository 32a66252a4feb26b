// Enskog's collision rates of a mixture (the scene's [[species]]), from the
// mixture contact values of common/geometry.h: the time unit of a mixture's
// run, and the rates the physics tests compare the engine's with.
#pragma once
#include <vector>

#include "simulate/scene/scene.h"

namespace coolgas {

// rate[i][j]: collisions per unit time of one particle of species i with
// particles of species j, the species' Maxwellians at temperatures T[k]
// (one per species), in the scene's box with its species counts.
std::vector<std::vector<double>> enskog_pair_rates(const Scene& s, const std::vector<double>& T);

// Collisions per particle per unit time, the number-weighted mean of the
// rows' sums, at a common temperature T.
double enskog_mean_rate(const Scene& s, double T);

// The temperature at which that mean rate is 1: the mean collision time of
// the mixture is the time unit (its T0, as unit_time_temperature is the
// equal particles').
double mixture_unit_time_temperature(const Scene& s);

}  // namespace coolgas
