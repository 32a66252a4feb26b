// Equilibrium hard-sphere kinetic theory that fixes the time unit
// (tests/physics/README.md): Enskog collision frequency with the Carnahan–Starling
// contact value, ω = 4 n σ² g(σ) √(π T / m).
#pragma once
#include <cmath>

namespace coolgas {

// Carnahan–Starling pair correlation at contact, g(σ) = (1 − φ/2) / (1 − φ)³.
inline double contact_value(double phi) { return (1.0 - 0.5 * phi) / std::pow(1.0 - phi, 3); }

// The temperature at which ω = 1, i.e. the mean collision time is the time unit:
// T0 = 1 / (π (4 n g(σ))²).
inline double unit_time_temperature(double n, double phi) {
  const double a = 4.0 * n * contact_value(phi);
  return 1.0 / (M_PI * a * a);
}

}  // namespace coolgas
