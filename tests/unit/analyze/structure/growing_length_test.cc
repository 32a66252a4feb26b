// L_t and the correlation lengths against configurations of known structure:
// random spheres of radius R (S known exactly), and density and velocity
// waves of one wave vector (C(r) = sin(kr)/(kr), first zero at r = pi/k).
#include "analyze/structure/growing_length.h"

#include <gtest/gtest.h>

#include <cmath>

#include "analyze/structure/correlation.h"
#include "analyze/structure/frame_structure.h"
#include "common/random.h"
#include "tests/unit/analyze/structure/test_configurations.h"

namespace coolgas {
namespace {

// Overlapping random spheres of radius R = 2 filled with 33 points each:
// S(k) = 1 + 32 F(kR)^2 on average (test_configurations.h). L_t measured on
// the grid equals, within 5 %, L_t of that exact S on the same shells, and
// that is the continuum value 2 pi/<k> with <k> R = 1.21 for the 10 % cut
// (the integral of x F^2 over that of F^2 up to F^2 = 0.1 at x = 2.65).
TEST(GrowingLength, RandomSpheresGiveTheLengthOfTheirFormFactor) {
  const double L = 64, R = 2;
  const int per_sphere = 33;
  const auto p = test::sphere_points(320, per_sphere, R, L, 31);
  FrameStructure fs(64, Geometry(3));
  const auto shells = fs.spectrum(L, p, {});
  const PeakLength measured = peak_length(shells, 1, 0.1);
  std::vector<Shell> exact = shells;
  for (Shell& s : exact) s.S = 1 + (per_sphere - 1) * std::pow(test::sphere_form_factor(s.k * R), 2);
  const PeakLength expected = peak_length(exact, 1, 0.1);
  EXPECT_NEAR(measured.L / expected.L, 1, 0.05) << measured.L << " vs " << expected.L;
  EXPECT_NEAR(expected.k_mean * R, 1.21, 0.06);
  EXPECT_GE(measured.shells, 8);
}

// The cut rule itself on a made-up spectrum: shells 1..3 above 10 % of the
// excess, shell 4 at it, so <k> = (1*10 + 2*6 + 3*2) / 18.
TEST(GrowingLength, FirstMomentStopsAtTheCut) {
  std::vector<Shell> s;
  const double S[] = {10, 6, 2, 1.9, 5, 1};
  for (int i = 0; i < 6; ++i) s.push_back({i + 1, double(i + 1), S[i], 0, 1});
  const PeakLength p = peak_length(s, 1, 0.1);  // threshold 1 + 0.9 = 1.9
  EXPECT_EQ(p.shells, 3);
  EXPECT_DOUBLE_EQ(p.k_mean, 28.0 / 18);
  EXPECT_DOUBLE_EQ(p.L, 2 * M_PI * 18 / 28);
  EXPECT_EQ(p.k_cut, 4);
  EXPECT_EQ(p.k_peak, 1);
}

// Points whose density is modulated as 1 + 0.8 cos(2 pi x / lambda): the
// correlation of the density is cos(k.r), whose shell average sin(kr)/(kr)
// first vanishes at r = lambda/2. Velocities v_y = sin(2 pi z / lambda) give
// the same for the momentum field.
TEST(GrowingLength, WavesGiveTheirCorrelationLengths) {
  const double L = 32, lambda = L / 2, k = 2 * M_PI / lambda;
  Random rng(41);
  std::vector<double> p, v;
  while (p.size() < 3 * 40000) {
    const double x = L * rng.uniform(), y = L * rng.uniform(), z = L * rng.uniform();
    if (1.8 * rng.uniform() > 1 + 0.8 * std::cos(k * x)) continue;
    p.insert(p.end(), {x, y, z});
    v.insert(v.end(), {0.0, std::sin(k * z), 0.0});
  }
  FrameStructure fs(32, Geometry(3));
  fs.spectrum(L, p, {});
  const double L_C = first_zero(fs.density_correlation(L));
  const double L_v = first_zero(fs.momentum_correlation(L, p, v, {}));
  EXPECT_NEAR(L_C, lambda / 2, 0.05 * lambda);
  EXPECT_NEAR(L_v, lambda / 2, 0.05 * lambda);
}

// Random spheres: C(r) of the density is the spheres' overlap volume, which
// ends at r = 2R; the coarse-graining (CIC, one grid spacing h) moves the
// zero by at most about h.
TEST(GrowingLength, RandomSpheresDecorrelateAtTheirDiameter) {
  const double L = 64, R = 3;
  const auto p = test::sphere_points(200, 110, R, L, 32);
  FrameStructure fs(64, Geometry(3));
  fs.spectrum(L, p, {});
  EXPECT_NEAR(first_zero(fs.density_correlation(L)), 2 * R, 1.0);
}

}  // namespace
}  // namespace coolgas
