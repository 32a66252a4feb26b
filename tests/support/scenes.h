// Scenes for engine tests, built in code (the parser has tests of its own).
#pragma once
#include <cmath>
#include <optional>

#include "simulate/scene/scene.h"

namespace coolgas::test {

inline Scene elastic_scene(std::int64_t N, double phi, std::int64_t seed = 1) {
  Scene s;
  s.N = N;
  s.phi = phi;
  s.L = std::cbrt(double(N) * M_PI / (6.0 * phi));
  s.seed = seed;
  s.t_end = 1;
  return s;
}

inline Scene inelastic_scene(std::int64_t N, double phi, double r0, double delta, std::int64_t seed = 1) {
  Scene s = elastic_scene(N, phi, seed);
  s.model = CollisionModel::kInelastic;
  s.set_parameter("r0", r0);
  s.set_parameter("delta", delta);
  return s;
}

// The scene in `dimension` (3, 2: hard disks, or 1: hard rods), with the
// same N and phi: the box side follows (in 2D phi is the area fraction
// N pi / (4 L^2), in 1D the line fraction N / L).
inline Scene in_dimension(Scene s, int dimension) {
  s.dimension = dimension;
  if (dimension == 2) s.L = std::sqrt(double(s.N) * M_PI / (4.0 * s.phi));
  if (dimension == 1) s.L = double(s.N) / s.phi;
  return s;
}

inline Scene disk_scene(std::int64_t N, double phi, std::int64_t seed = 1) {
  return in_dimension(elastic_scene(N, phi, seed), 2);
}

inline Scene inelastic_disk_scene(std::int64_t N, double phi, double r0, double delta, std::int64_t seed = 1) {
  return in_dimension(inelastic_scene(N, phi, r0, delta, seed), 2);
}

inline Scene rod_scene(std::int64_t N, double phi, std::int64_t seed = 1) {
  return in_dimension(elastic_scene(N, phi, seed), 1);
}

inline Scene inelastic_rod_scene(std::int64_t N, double phi, double r0, double delta, std::int64_t seed = 1) {
  return in_dimension(inelastic_scene(N, phi, r0, delta, seed), 1);
}

// The scene's particles made rough: collision.beta = beta, the inertia
// (system.inertia) that of a uniform ball unless given.
inline Scene rough(Scene s, double beta, std::optional<double> inertia = std::nullopt) {
  s.set_parameter("beta", beta);
  s.inertia = inertia;
  return s;
}

// The scene as a binary mixture ([[species]]): a fraction x of unit
// particles and 1 - x of diameter `ratio` (masses diameter^d unless `mass2`
// is given), the box side for the scene's phi. Apply after in_dimension.
inline Scene binary_mixture(Scene s, double x, double ratio, std::optional<double> mass2 = std::nullopt) {
  s.species = {{x, 1.0, std::nullopt}, {1.0 - x, ratio, mass2}};
  s.L = s.geometry().box_side_for(s.unit_particles(), s.phi);
  return s;
}

}  // namespace coolgas::test
