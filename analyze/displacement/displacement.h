// Displacements of the particles from a reference dump: the mean-square
// displacement and the velocity autocorrelation of coolgas-displacement.
//
// The dumps hold positions wrapped into the box and the periodic image
// counts the engine keeps for each particle (data-schema/h5md-profile.md:
// unwrapped = position + L image), so a particle's displacement between any
// two dumps is exact, however far apart they are and however often it
// crossed the box: nothing is guessed from the dump spacing.
//   msd(t)  = <|r(t) - r(t_ref)|^2>          over the particles [sigma^2]
//   vacf(t) = <v(t) . v(t_ref)>               [sigma^2 omega0^2]
//   T(t)    = <|v(t)|^2> / d                  (unit masses)
// Free flight gives msd = <|v|^2> (t - t_ref)^2 = d T (t - t_ref)^2 exactly,
// before the first collisions.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "common/geometry.h"

namespace coolgas {

struct Displacement {
  int d = 3;             // the dimension
  double msd = 0;        // <|dr|^2> [sigma^2]
  double msd_err = 0;    // standard error of that mean over the particles
  double vacf = 0;       // <v(t).v(t_ref)> [sigma^2 omega0^2]
  double vacf_norm = 0;  // vacf / <|v(t_ref)|^2> (0 if every particle rested at t_ref)
  double T = 0;          // <|v(t)|^2>/d [m sigma^2 omega0^2]
  // msd / (2 d dt), the diffusion coefficient it implies over dt [sigma^2 omega0]; 0 at dt = 0.
  double D_apparent(double dt) const { return dt != 0 ? msd / (2.0 * d * dt) : 0.0; }
};

// The reference: each particle's unwrapped position and velocity at t_ref.
class DisplacementOrigin {
 public:
  // positions x0 y0 z0 x1 ... in [0, L), images the same shape, velocities
  // likewise (the coordinates past the dimension 0).
  DisplacementOrigin(double L, std::span<const double> positions, std::span<const std::int32_t> images,
                     std::span<const double> velocities, Geometry g);
  std::size_t particles() const { return unwrapped_.size() / 3; }
  double temperature() const { return T_; }  // T(t_ref)
  // Displacements of the frame (same particles, same order) from here.
  Displacement from_here(double L, std::span<const double> positions, std::span<const std::int32_t> images,
                         std::span<const double> velocities) const;

 private:
  Geometry g_;
  std::vector<double> unwrapped_, velocity_;
  double T_ = 0;
};

}  // namespace coolgas
