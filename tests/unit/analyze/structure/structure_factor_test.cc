// S(k) from the cloud-in-cell grid against known answers: uniformly random
// points (S = 1, or s = sum m^2 / sum m with weights), the Bragg peaks of an
// FCC lattice, and the exact sum over particles within the alias bound stated
// in analyze/structure/structure_factor.h.
#include "analyze/structure/structure_factor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "analyze/structure/cloud_in_cell.h"
#include "analyze/structure/frame_structure.h"
#include "common/random.h"
#include "tests/unit/analyze/structure/test_configurations.h"

namespace coolgas {
namespace {

TEST(StructureFactor, ShellsRoundTheWaveNumber) {
  EXPECT_EQ(shell_of(1), 1);
  EXPECT_EQ(shell_of(2), 1);   // sqrt 2 = 1.41
  EXPECT_EQ(shell_of(3), 2);   // 1.73
  EXPECT_EQ(shell_of(6), 2);   // 2.45
  EXPECT_EQ(shell_of(7), 3);   // 2.65
  EXPECT_EQ(shell_of(12), 3);  // 3.46
  EXPECT_EQ(shell_of(13), 4);  // 3.61
}

// Sum over aliases of the CIC window is 1 and of its square is C1 (Jing
// 2005's closed form for CIC): checked by summing the aliases directly.
TEST(StructureFactor, CicWindowSumsOverAliases) {
  for (double u : {0.01, 0.1, 0.25, 0.4}) {
    double w = 0, w2 = 0;
    for (int n = -20000; n <= 20000; ++n) w += cic_window(u + n), w2 += std::pow(cic_window(u + n), 2);
    EXPECT_NEAR(w, 1, 1e-4) << u;
    EXPECT_NEAR(w2, cic_alias_sum(u), 1e-12) << u;
  }
}

// Poisson points: every shell's S is 1 within its standard error (4 sigma,
// 8 shells), and the mean over all shells within 3 of its errors.
TEST(StructureFactor, UniformRandomPointsGiveOne) {
  const double L = 20;
  const auto p = test::uniform_points(30000, L, 11);
  FrameStructure fs(32, Geometry(3));
  const auto shells = fs.spectrum(L, p, {});
  ASSERT_EQ(shells.size(), 8u);
  test::expect_poisson_shells(shells);
}

// With weights the shot-noise level is s = sum m^2 / sum m.
TEST(StructureFactor, WeightedRandomPointsGiveTheWeightedShotNoise) {
  const double L = 20;
  const auto p = test::uniform_points(20000, L, 12);
  Random rng(13);
  std::vector<double> m(20000);
  for (double& x : m) x = 1 + double(rng.below(20));
  const Weights w = weights_of(m, m.size());
  FrameStructure fs(32, Geometry(3));
  for (const Shell& s : fs.spectrum(L, p, m)) EXPECT_NEAR(s.S / w.shot, 1, 4 * s.S_err / w.shot) << s.index;
  EXPECT_GT(w.shot, 10);
}

// FCC lattice (a = 2, 6^3 cells, 864 sites), shifted off the grid: S = N at
// reciprocal lattice vectors G = (2 pi/a)(h, k, l), h k l all even or all odd,
// zero elsewhere. Off-peak the estimate holds only the residual of the shot
// noise correction, s (1 - C1/W^2) = O(u^4).
TEST(StructureFactor, FccLatticeHasBraggPeaksOnlyAtItsReciprocalLattice) {
  const int cells = 6, n = 48;
  const double L = 12, offset[3] = {0.137, 0.291, 0.053};
  const auto p = test::fcc_points(cells, L, offset);
  const double N = double(p.size() / 3);
  // Bragg vectors per shell, in one half space as the shells count their modes.
  std::map<int, int> bragg;
  for (int h = -4; h <= 4; ++h)
    for (int k = -4; k <= 4; ++k)
      for (int l = -4; l <= 4; ++l) {
        const bool all_even = h % 2 == 0 && k % 2 == 0 && l % 2 == 0;
        const bool all_odd = h % 2 != 0 && k % 2 != 0 && l % 2 != 0;
        if (!(all_even || all_odd) || (h == 0 && k == 0 && l == 0)) continue;
        const int s = shell_of(long(cells) * cells * (h * h + k * k + l * l));
        if (s < n / 2) bragg[s] += 1;
      }
  for (auto& [s, c] : bragg) c /= 2;  // G and -G are one mode
  EXPECT_EQ(bragg.at(10), 4);  // (111): |G| L/2pi = 6 sqrt 3 = 10.4, 8 vectors
  EXPECT_EQ(bragg.at(12), 3);  // (200): 12, 6 vectors
  FrameStructure fs(n, Geometry(3));
  const auto shells = fs.spectrum(L, p, {});
  double off_peak = 0, lowest_peak = 1e300;
  for (const Shell& s : shells) {
    const auto b = bragg.find(s.index);
    if (b == bragg.end()) {
      off_peak = std::max(off_peak, std::abs(s.S));
      continue;
    }
    const double per_vector = s.S * s.modes / (N * b->second);  // 1 without window effects
    lowest_peak = std::min(lowest_peak, s.S);
    EXPECT_NEAR(per_vector, 1, 0.25) << "shell " << s.index;
  }
  EXPECT_LT(off_peak, 0.05);
  EXPECT_GT(lowest_peak, 100 * off_peak);
}

// The grid estimate against the exact sum, shell by shell, within the bound of
// structure_factor.h: |S_grid - S_exact| <= 3 * 2 (1/W - 1) sqrt(s S), with W
// the window at the shell's outer edge (1/W - 1 ~ exp((pi^2/3) |u|^2) - 1).
void expect_grid_matches_direct(const std::vector<double>& p, double L, int n, int shells_checked) {
  FrameStructure fs(n, Geometry(3));
  const auto shells = fs.spectrum(L, p, {});
  const auto direct = direct_structure_factor(L, p, {}, shells_checked, Geometry(3));
  for (int s = 1; s <= shells_checked; ++s) {
    const double u = (s + 0.5) / n, alias = std::exp(M_PI * M_PI / 3 * u * u) - 1;
    const double bound = 3 * 2 * alias * std::sqrt(direct[s - 1]);
    EXPECT_NEAR(shells[s - 1].S, direct[s - 1], bound) << "shell " << s;
    EXPECT_GT(std::abs(shells[s - 1].S - direct[s - 1]), 0) << "the grid is not the exact sum";
  }
}

TEST(StructureFactor, GridMatchesTheExactSumForRandomPoints) {
  expect_grid_matches_direct(test::uniform_points(5000, 16, 21), 16, 32, 3);
}

TEST(StructureFactor, GridMatchesTheExactSumForClusteredPoints) {
  expect_grid_matches_direct(test::sphere_points(60, 80, 2.5, 24, 22), 24, 32, 3);
}

}  // namespace
}  // namespace coolgas
