// Point sets with known structure for the coolgas-structure tests, drawn with
// the portable generator (common/random.h) so every platform sees the same points.
#pragma once
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "analyze/structure/structure_factor.h"
#include "common/random.h"

namespace coolgas::test {

// Poisson points: every shell's S is 1 within 4 of its standard errors, and
// the mean over all shells (each weighted by its modes) within 3 of its errors.
inline void expect_poisson_shells(const std::vector<Shell>& shells) {
  double sum = 0, modes = 0;
  for (const Shell& s : shells) {
    EXPECT_NEAR(s.S, 1, 4 * s.S_err) << "shell " << s.index;
    sum += s.S * s.modes;
    modes += s.modes;
  }
  EXPECT_NEAR(sum / modes, 1, 3 / std::sqrt(modes));
}

// n points uniformly in the periodic box [0, L)^3.
inline std::vector<double> uniform_points(std::size_t n, double L, std::uint64_t seed) {
  Random rng(seed);
  std::vector<double> p(3 * n);
  for (double& x : p) x = L * rng.uniform();
  return p;
}

// The face-centred cubic lattice of cells cells^3 in a box of side L (lattice
// constant a = L/cells, 4 sites per cell), shifted by `offset`.
inline std::vector<double> fcc_points(int cells, double L, const double offset[3]) {
  const double a = L / cells;
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  std::vector<double> p;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int k = 0; k < cells; ++k)
        for (const auto& b : basis) {
          const int c[3] = {i, j, k};
          for (int d = 0; d < 3; ++d) p.push_back(std::fmod(a * (c[d] + b[d]) + offset[d], L));
        }
  return p;
}

// A two-phase configuration: `spheres` spheres of radius R with centres
// uniform in the box (overlaps allowed: independent spheres), each filled with
// `per_sphere` points uniform inside it, wrapped into the box. Its structure
// factor is exactly, on average,
//   S(k) = 1 + (per_sphere - 1) F(kR)^2,  F(x) = 3 (sin x - x cos x) / x^3,
// (points of one sphere are correlated through its centre only; different
// spheres are independent).
inline std::vector<double> sphere_points(int spheres, int per_sphere, double R, double L, std::uint64_t seed) {
  Random rng(seed);
  std::vector<double> p;
  for (int s = 0; s < spheres; ++s) {
    double c[3];
    for (double& x : c) x = L * rng.uniform();
    for (int q = 0; q < per_sphere;) {
      double d[3];
      for (double& x : d) x = R * (2 * rng.uniform() - 1);
      if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > R * R) continue;  // rejection: uniform in the ball
      for (int a = 0; a < 3; ++a) {
        const double x = c[a] + d[a];
        p.push_back(x - L * std::floor(x / L));
      }
      ++q;
    }
  }
  return p;
}

// The sphere's form factor F(x) above.
inline double sphere_form_factor(double x) { return 3 * (std::sin(x) - x * std::cos(x)) / (x * x * x); }

}  // namespace coolgas::test
