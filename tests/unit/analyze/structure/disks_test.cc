// S(k) in 2D (disks: every z is 0, an n^2 grid and circular shells) against
// known answers: uniformly random points in the square give S = 1, a square
// lattice has Bragg peaks S = N exactly at its reciprocal lattice and nothing
// elsewhere, and the grid estimate agrees with the exact sum over the points.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "analyze/structure/frame_structure.h"
#include "analyze/structure/structure_factor.h"
#include "common/random.h"
#include "tests/unit/analyze/structure/test_configurations.h"

namespace coolgas {
namespace {

// n points uniform in [0, L)^2, as 3-vectors with z = 0.
std::vector<double> uniform_disks(std::size_t n, double L, std::uint64_t seed) {
  Random rng(seed);
  std::vector<double> p(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) p[3 * i] = L * rng.uniform(), p[3 * i + 1] = L * rng.uniform();
  return p;
}

// The square lattice of cells^2 sites (constant a = L/cells), shifted by (ox, oy).
std::vector<double> square_lattice(int cells, double L, double ox, double oy) {
  const double a = L / cells;
  std::vector<double> p;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) p.insert(p.end(), {std::fmod(a * i + ox, L), std::fmod(a * j + oy, L), 0.0});
  return p;
}

TEST(DiskStructureFactor, UniformRandomPointsGiveOne) {
  const double L = 40;
  const auto p = uniform_disks(20000, L, 31);
  FrameStructure fs(64, Geometry(2));
  const auto shells = fs.spectrum(L, p, {});
  ASSERT_EQ(shells.size(), 16u);
  test::expect_poisson_shells(shells);
  // A circle of radius s holds about pi s modes in a half plane (3D: 2 pi s^2).
  EXPECT_NEAR(shells[9].modes, M_PI * 10, 0.2 * M_PI * 10);
}

// Square lattice, a = 2, 8^2 sites, off the grid: S = N at G = (2 pi/a)(h, k),
// (h, k) != 0, i.e. shell round(8 sqrt(h^2 + k^2)); the shells between hold
// only the residual of the shot-noise correction.
TEST(DiskStructureFactor, SquareLatticeHasBraggPeaksOnlyAtItsReciprocalLattice) {
  const int cells = 8, n = 64;
  const double L = 16;
  const auto p = square_lattice(cells, L, 0.137, 0.291);
  const double N = double(p.size() / 3);
  std::map<int, int> bragg;  // Bragg vectors per shell, half of them (G and -G are one mode)
  for (int h = -3; h <= 3; ++h)
    for (int k = -3; k <= 3; ++k)
      if (h != 0 || k != 0) bragg[shell_of(long(cells) * cells * (h * h + k * k))] += 1;
  for (auto& [s, c] : bragg) c /= 2;
  EXPECT_EQ(bragg.at(8), 2);   // (1 0), (0 1)
  EXPECT_EQ(bragg.at(11), 2);  // (1 1), (1 -1): 8 sqrt 2 = 11.3
  FrameStructure fs(n, Geometry(2));
  double off_peak = 0;
  for (const Shell& s : fs.spectrum(L, p, {})) {
    const auto b = bragg.find(s.index);
    if (b == bragg.end()) {
      off_peak = std::max(off_peak, std::abs(s.S));
      continue;
    }
    EXPECT_NEAR(s.S * s.modes / (N * b->second), 1, 0.1) << "shell " << s.index;
  }
  EXPECT_LT(off_peak, 0.02);
}

// The grid against the exact sum over the points, within the alias bound of
// structure_factor.h; and the exact sum of the lattice is N at its peak.
TEST(DiskStructureFactor, GridMatchesTheExactSum) {
  const double L = 24;
  const auto p = uniform_disks(4000, L, 32);
  FrameStructure fs(32, Geometry(2));
  const auto shells = fs.spectrum(L, p, {});
  const auto direct = direct_structure_factor(L, p, {}, 3, Geometry(2));
  for (int s = 1; s <= 3; ++s) {
    const double u = (s + 0.5) / 32, alias = std::exp(M_PI * M_PI / 3 * u * u) - 1;
    EXPECT_NEAR(shells[s - 1].S, direct[s - 1], 3 * 2 * alias * std::sqrt(direct[s - 1])) << "shell " << s;
  }
  // A lattice with a = 2 in a box of 8: shell 4 holds the peak (1 0), (0 1) (S = N = 16) among modes of S = 0.
  int modes = 0;
  for (int a = -4; a <= 4; ++a)
    for (int b = -4; b <= 4; ++b) modes += shell_of(long(a) * a + long(b) * b) == 4;
  const auto exact = direct_structure_factor(8, square_lattice(4, 8, 0.3, 0.1), {}, 4, Geometry(2));
  EXPECT_NEAR(exact[3], 16.0 * 4 / modes, 1e-9);  // 4 of the shell's vectors are Bragg vectors
  EXPECT_NEAR(exact[0], 0, 1e-9);
}

}  // namespace
}  // namespace coolgas
