// The box of a scene in its dimension D: a periodic cube of side L holding
// spheres (D = 3), a periodic square holding disks (D = 2), or a ring of
// length L holding rods (D = 1). phi is the fraction of the volume (area,
// length) the particles cover: a unit sphere covers pi/6 of a unit cube, a
// unit disk pi/4 of a unit square, a unit rod all of a unit length. The 3D forms are
// the ones coolgas has always computed, operation for operation, so a 3D
// scene's N, L and phi stay the same to the last bit.
#pragma once
#include <cmath>
#include <cstdint>

namespace coolgas {

// L^D.
inline double box_volume(double L, int dimension) { return dimension == 3 ? L * L * L : (dimension == 2 ? L * L : L); }

// phi of N unit particles in a box of side L.
inline double covered_fraction(double N, double L, int dimension) {
  if (dimension == 1) return N / L;
  return dimension == 3 ? N * M_PI / (6.0 * L * L * L) : N * M_PI / (4.0 * L * L);
}

// N (not rounded) at covered fraction phi in a box of side L.
inline double particles_at(double phi, double L, int dimension) {
  if (dimension == 1) return phi * L;
  return dimension == 3 ? phi * 6.0 * L * L * L / M_PI : phi * 4.0 * L * L / M_PI;
}

// L of the box in which N unit particles cover phi.
inline double box_side_for(double N, double phi, int dimension) {
  if (dimension == 1) return N / phi;
  return dimension == 3 ? std::cbrt(N * M_PI / (6.0 * phi)) : std::sqrt(N * M_PI / (4.0 * phi));
}

}  // namespace coolgas
