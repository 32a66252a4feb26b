// Equilibrium hard-sphere (hard-disk, hard-rod) kinetic theory that fixes the
// time unit (tests/physics/README.md): the Enskog collision frequency in d
// dimensions, ω = (2 π^((d−1)/2) / Γ(d/2)) n σ^(d−1) g(σ) √(T/m), that is
// ω = 4 n σ² g(σ) √(π T / m) for spheres, ω = 2 n σ g(σ) √(π T / m) for
// disks and (Γ(1/2) = √π) ω = 2 n g(σ) √(T / (π m)) for rods, with the
// contact value g(σ) of the dimension's equation of state.
#pragma once
#include <cmath>

namespace coolgas {

// Carnahan–Starling pair correlation at contact, g(σ) = (1 − φ/2) / (1 − φ)³.
inline double contact_value(double phi) { return (1.0 - 0.5 * phi) / std::pow(1.0 - phi, 3); }

// Hard disks: Henderson's contact value g(σ) = (1 − 7φ/16) / (1 − φ)²
// (D. Henderson, Mol. Phys. 30, 971 (1975)), φ the area fraction.
inline double contact_value_2d(double phi) { return (1.0 - 7.0 * phi / 16.0) / ((1.0 - phi) * (1.0 - phi)); }

// Hard rods on a line: the exact contact value of the Tonks gas,
// g(σ) = 1 / (1 − φ), φ = n σ the line fraction (L. Tonks, Phys. Rev. 50,
// 955 (1936)): the gaps between neighbours are independent and exponential,
// of mean (1 − φ)/n, so the density of neighbours at contact is n/(1 − φ).
// In 1D Enskog's rate with it is exact for an equilibrium gas.
inline double contact_value_1d(double phi) { return 1.0 / (1.0 - phi); }

// The temperature at which ω = 1, i.e. the mean collision time is the time
// unit: T0 = 1 / (π (4 n g(σ))²) in 3D, 1 / (π (2 n g(σ))²) in 2D and
// π / (2 n g(σ))² in 1D, with n the number density (per volume, area, length).
inline double unit_time_temperature(double n, double phi, int dimension = 3) {
  if (dimension == 1) {
    const double a = 2.0 * n * contact_value_1d(phi);
    return M_PI / (a * a);
  }
  const double a = dimension == 3 ? 4.0 * n * contact_value(phi) : 2.0 * n * contact_value_2d(phi);
  return 1.0 / (M_PI * a * a);
}

}  // namespace coolgas
