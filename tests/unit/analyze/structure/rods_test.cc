// S(k) in 1D (rods on a ring: y = z = 0, n grid points, k = 2 pi s/L, one
// independent mode per shell) against known answers: uniformly random points
// give S = 1 on average, a regular lattice has Bragg peaks S = N exactly at
// its reciprocal lattice and 0 elsewhere, the grid estimate agrees with the
// exact sum over the points, and C(r) along the line of a density wave is
// cos(kr) itself (no shell average), first zero at a quarter wavelength.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analyze/structure/frame_structure.h"
#include "analyze/structure/structure_factor.h"
#include "analyze/structure/tool.h"
#include "common/random.h"
#include "common/trajectory/h5md_writer.h"
#include "common/tsv.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

// n points uniform on the ring [0, L), as 3-vectors with y = z = 0.
std::vector<double> uniform_rods(std::size_t n, double L, std::uint64_t seed) {
  Random rng(seed);
  std::vector<double> p(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) p[3 * i] = L * rng.uniform();
  return p;
}

// m sites a = L/m apart, shifted by `offset`.
std::vector<double> rod_lattice(int m, double L, double offset) {
  std::vector<double> p;
  for (int i = 0; i < m; ++i) p.insert(p.end(), {std::fmod(L / m * i + offset, L), 0.0, 0.0});
  return p;
}

// Each shell is one mode (k and -k), an exponential variable of mean 1 for
// Poisson points: its S_err is S itself, and the mean over the n/4 shells is
// 1 within 3/sqrt(n/4).
TEST(RodStructureFactor, UniformRandomPointsGiveOne) {
  const double L = 3000;
  const auto p = uniform_rods(30000, L, 51);
  FrameStructure fs(1024, Geometry(1));
  const auto shells = fs.spectrum(L, p, {});
  ASSERT_EQ(shells.size(), 256u);
  double sum = 0;
  for (const Shell& s : shells) {
    EXPECT_EQ(s.modes, 1) << "shell " << s.index;
    EXPECT_EQ(s.S_err, s.S) << "shell " << s.index;
    EXPECT_NEAR(s.k, 2 * M_PI * s.index / L, 1e-12) << "shell " << s.index;
    sum += s.S;
  }
  EXPECT_NEAR(sum / 256, 1, 3 / std::sqrt(256.0));
}

// 8 sites a = 2 apart on a ring of 16, off the grid: S = N = 8 at shells 8,
// 16, ... (k = 2 pi h/a), within the CIC correction's accuracy up to an
// eighth of the grid (at shell n/4 a lattice's aliases, which do not average
// out as a random set's do, leave it 25 % off); the other shells hold only
// the residual of the shot-noise correction. The exact sum is N and 0 to
// round-off.
TEST(RodStructureFactor, LatticeHasBraggPeaksOnlyAtItsReciprocalLattice) {
  const double L = 16;
  const auto p = rod_lattice(8, L, 0.137);
  FrameStructure fs(128, Geometry(1));
  double off_peak = 0;
  for (const Shell& s : fs.spectrum(L, p, {})) {
    if (s.index % 8 != 0) {
      off_peak = std::max(off_peak, std::abs(s.S));
    } else if (s.index <= 16) {
      EXPECT_NEAR(s.S / 8, 1, 0.1) << "shell " << s.index;
    }
  }
  EXPECT_LT(off_peak, 0.02);
  const auto exact = direct_structure_factor(L, p, {}, 16, Geometry(1));
  for (int s = 1; s <= 16; ++s) EXPECT_NEAR(exact[s - 1], s % 8 == 0 ? 8.0 : 0.0, 1e-9) << "shell " << s;
}

// The grid against the exact sum over the points, within the alias bound of
// structure_factor.h.
TEST(RodStructureFactor, GridMatchesTheExactSum) {
  const double L = 64;
  const auto p = uniform_rods(2000, L, 52);
  FrameStructure fs(64, Geometry(1));
  const auto shells = fs.spectrum(L, p, {});
  const auto direct = direct_structure_factor(L, p, {}, 4, Geometry(1));
  for (int s = 1; s <= 4; ++s) {
    const double u = (s + 0.5) / 64, alias = std::exp(M_PI * M_PI / 3 * u * u) - 1;
    EXPECT_NEAR(shells[s - 1].S, direct[s - 1], 3 * 2 * alias * std::sqrt(direct[s - 1])) << "shell " << s;
  }
}

// Density 1 + 0.8 cos(kx), k = 2 pi/lambda: along a line C(r) is cos(kr),
// whose first zero is lambda/4 (in 3D the shell average sin(kr)/(kr) puts it
// at lambda/2). Uniform points with v_x = sin(kx) give the same for C_v.
TEST(RodStructureFactor, CorrelationsRunAlongTheLine) {
  const double L = 256, lambda = L / 4, k = 2 * M_PI / lambda;
  Random rng(53);
  std::vector<double> p, v;
  while (p.size() < 3 * 100000) {
    const double x = L * rng.uniform();
    if (1.8 * rng.uniform() > 1 + 0.8 * std::cos(k * x)) continue;
    p.insert(p.end(), {x, 0.0, 0.0});
  }
  FrameStructure fs(256, Geometry(1));
  fs.spectrum(L, p, {});
  EXPECT_NEAR(first_zero(fs.density_correlation(L)), lambda / 4, 0.02 * lambda);
  const auto u = uniform_rods(100000, L, 54);
  for (std::size_t i = 0; i < u.size(); i += 3) v.insert(v.end(), {std::sin(k * u[i]), 0.0, 0.0});
  fs.spectrum(L, u, {});
  EXPECT_NEAR(first_zero(fs.momentum_correlation(L, u, v, {})), lambda / 4, 0.02 * lambda);
}

// The tool on a 1D file from the real writer: y = S / L_t (x = k L_t), the
// grid is n points on the ring, the table says its dimension.
TEST(RodStructureFactor, TheToolReadsA1DFile) {
  const std::string path = test::scratch_dir("structure_rods") + "/run.h5";
  const double L = 500;
  const auto p = uniform_rods(5000, L, 55);
  {
    RunParameters par;
    par.N = 5000;
    par.L = L;
    H5mdWriter w = H5mdWriter::create(path, par, false, Geometry(1));
    const std::vector<double> vel(p.size(), 0.5);
    const std::vector<std::int32_t> img(p.size(), 0);
    w.add_frame({2.0, 10, 0, p.data(), img.data(), vel.data()});
  }
  StructureOptions o;
  o.input = path;
  std::stringstream out;
  run_structure(o, out);
  const Table t = read_table(out, "out");
  EXPECT_EQ(t.get("dimension"), "1");
  EXPECT_EQ(t.get("grid"), "500 points on the ring, spacing 1 sigma");
  ASSERT_EQ(t.rows.size(), 125u);
  for (const auto& r : t.rows) {
    const double L_t = r[t.column("x")] / r[t.column("k")];
    EXPECT_NEAR(r[t.column("y")], r[t.column("S")] / L_t, 1e-12 * std::abs(r[t.column("S")] / L_t));
    EXPECT_EQ(r[t.column("modes")], 1);
  }
}

}  // namespace
}  // namespace coolgas
