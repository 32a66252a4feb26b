// coolgas-fields' kernels (analyze/fields/): the longitudinal/transverse split
// on flows whose split is known exactly, and the noise levels of
// independent velocities.
#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <numbers>
#include <random>
#include <vector>

#include "analyze/fields/cell_fields.h"
#include "analyze/fields/fields_table.h"
#include "analyze/fields/flow_split.h"
#include "analyze/fields/tool.h"
#include "common/error.h"

namespace coolgas {
namespace {

constexpr double kPi = std::numbers::pi;

// One particle at the centre of each of the n^d cells of a box of side L,
// with velocity v(position) in x0 y0 z0 x1 ... order.
struct Lattice {
  std::vector<double> position, velocity;
};
template <class V>
Lattice lattice(int n, Geometry g, double L, V v) {
  Lattice out;
  const double h = L / n;
  for (int iz = 0; iz < g.along(2, n); ++iz)
    for (int iy = 0; iy < g.along(1, n); ++iy)
      for (int ix = 0; ix < n; ++ix) {
        const double r[3] = {(ix + 0.5) * h, g.spans(1) ? (iy + 0.5) * h : 0, g.spans(2) ? (iz + 0.5) * h : 0};
        const auto u = v(r);
        for (int a = 0; a < 3; ++a) out.position.push_back(r[a]), out.velocity.push_back(u[a]);
      }
  return out;
}

struct Split {
  CellFields f;
  FieldEnergies e;
  FlowSplit s;
};
Split split(int n, Geometry g, double L, const std::vector<double>& r, const std::vector<double>& v) {
  Split out{cell_fields(n, g, L, r, v, {}), {}, {}};
  out.e = field_energies(out.f);
  FourierGrid grid(n, g);
  out.s = flow_split(out.f, out.e.temperature, grid);
  return out;
}

// A shear wave u_x = U sin(2 pi y / L) over a uniform density is transverse
// alone: E_T = U^2/4 (the mean of u^2/2), E_L = 0, and its vorticity
// -du_x/dy has mean square (2 pi U / L)^2 / 2; all of it is flow.
TEST(FlowSplit, AShearWaveIsTransverseAlone) {
  for (int d : {2, 3}) {
    const Geometry g(d);
    const double L = 16, U = 0.7, k = 2 * kPi / L;
    const Lattice a = lattice(8, g, L, [&](const double* r) { return std::array<double, 3>{U * std::sin(k * r[1]), 0, 0}; });
    const Split s = split(8, g, L, a.position, a.velocity);
    EXPECT_NEAR(s.s.transverse, U * U / 4, 1e-12) << d << "D";
    EXPECT_NEAR(s.s.longitudinal, 0, 1e-12) << d << "D";
    EXPECT_NEAR(s.s.vorticity2, k * k * U * U / 2, 1e-12) << d << "D";
    EXPECT_NEAR(s.e.flow, s.e.kinetic, 1e-12) << d << "D";
    EXPECT_NEAR(s.e.kinetic, U * U / 4, 1e-12) << d << "D";
    // The whole of it in the shell of |k| = 2 pi / L.
    EXPECT_NEAR(s.s.shells[0].transverse, U * U / 4, 1e-12) << d << "D";
  }
}

// A sound wave u_x = U sin(2 pi x / L) is longitudinal alone, in every d
// (in 1D no other kind exists), and has no vorticity.
TEST(FlowSplit, ASoundWaveIsLongitudinalAlone) {
  for (int d : {1, 2, 3}) {
    const Geometry g(d);
    const double L = 16, U = 0.3, k = 2 * kPi / L;
    const Lattice a = lattice(8, g, L, [&](const double* r) { return std::array<double, 3>{U * std::sin(k * r[0]), 0, 0}; });
    const Split s = split(8, g, L, a.position, a.velocity);
    EXPECT_NEAR(s.s.longitudinal, U * U / 4, 1e-12) << d << "D";
    EXPECT_NEAR(s.s.transverse, 0, 1e-12) << d << "D";
    EXPECT_NEAR(s.s.vorticity2, 0, 1e-12) << d << "D";
  }
}

// Random positions and independent Gaussian velocities at temperature T.
struct Gas {
  std::vector<double> position, velocity;
};
Gas random_gas(int n_particles, Geometry g, double L, double T, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> at(0, L);
  std::normal_distribution<double> v(0, std::sqrt(T));
  Gas gas;
  for (int j = 0; j < n_particles; ++j)
    for (int a = 0; a < 3; ++a) {
      gas.position.push_back(a < g.d() ? at(rng) : 0);
      gas.velocity.push_back(a < g.d() ? v(rng) : 0);
    }
  return gas;
}

// Moving the whole gas changes no field: velocities are taken relative to
// the centre of mass, so a uniform translation has no flow, and adding one
// to a gas changes its energies only by round-off.
TEST(FlowSplit, AUniformTranslationHasNoFlow) {
  const Geometry g(3);
  Gas gas = random_gas(4000, g, 20, 1.0, 5);
  std::vector<double> still(gas.velocity.size(), 0.0), moving = still;
  for (std::size_t i = 0; i < moving.size(); i += 3) moving[i] = 2.5, moving[i + 1] = -1;
  const Split s = split(10, g, 20, gas.position, moving);
  // Zero but for the round-off of the centre of mass's velocity (E ~ 7 here).
  EXPECT_LT(s.s.transverse, 1e-15);
  EXPECT_LT(s.s.longitudinal, 1e-15);
  EXPECT_LT(s.e.kinetic, 1e-15);
  const Split a = split(10, g, 20, gas.position, gas.velocity);
  for (std::size_t i = 0; i < moving.size(); ++i) moving[i] += gas.velocity[i];
  const Split b = split(10, g, 20, gas.position, moving);
  EXPECT_NEAR(b.s.transverse, a.s.transverse, 1e-9 * a.s.transverse);
  EXPECT_NEAR(b.e.flow, a.e.flow, 1e-9 * a.e.flow);
}

// Independent velocities: the flow energies at their noise levels, each a
// sum of ~cells independent squares, so within a few times sqrt(2/(d cells)).
TEST(FlowSplit, IndependentVelocitiesSitAtTheNoiseLevels) {
  for (int d : {1, 2, 3}) {
    const Geometry g(d);
    const int n = d == 3 ? 16 : d == 2 ? 64 : 1024;
    const double L = d == 3 ? 32 : d == 2 ? 128 : 4096;
    const Gas gas = random_gas(40000, g, L, 0.8, 11 + d);
    const Split s = split(n, g, L, gas.position, gas.velocity);
    const double cells = s.f.cells(), tol = 5 * std::sqrt(2 / (d * cells));
    EXPECT_NEAR(s.e.temperature / 0.8, 1, 0.02) << d << "D";
    EXPECT_NEAR(s.e.flow / s.e.flow_noise, 1, tol) << d << "D";
    EXPECT_NEAR(s.s.longitudinal / s.s.longitudinal_noise, 1, 5 * std::sqrt(2 / cells)) << d << "D";
    if (d > 1) EXPECT_NEAR(s.s.transverse / s.s.transverse_noise, 1, tol) << d << "D";
    else EXPECT_EQ(s.s.transverse, 0);
    EXPECT_NEAR(s.e.density_variance, 1, 5 * std::sqrt(2 / cells)) << d << "D";
  }
}

// The slab's vorticity of the shear wave is the central difference of
// -du_x/dy, exactly -U cos(k y) sin(k h)/h at each cell; density one per cell.
TEST(FieldsSlab, AShearWavesVorticityIsItsCentralDifference) {
  for (int d : {2, 3}) {
    const Geometry g(d);
    const int n = 8;
    const double L = 16, U = 0.7, k = 2 * kPi / L, h = L / n;
    const Lattice a = lattice(n, g, L, [&](const double* r) { return std::array<double, 3>{U * std::sin(k * r[1]), 0, 0}; });
    const TableBlock b = slab_block(3, cell_fields(n, g, L, a.position, a.velocity, {}));
    ASSERT_EQ(b.rows.size(), std::size_t(n * n));
    for (const auto& row : b.rows) {
      EXPECT_EQ(row[0], 3);
      EXPECT_NEAR(row[3], 1 / g.power(h), 1e-12);
      EXPECT_NEAR(row[4], -U * std::cos(k * row[2]) * std::sin(k * h) / h, 1e-12) << d << "D y = " << row[2];
    }
  }
}

TEST(FieldCells, TheGridAndItsLimitsAreNamedByTheOption) {
  EXPECT_EQ(field_cells(100, 4, Geometry(3), 1e12), 24);
  EXPECT_EQ(field_cells(100, 1, Geometry(3), 1e12), 100);
  EXPECT_THROW(field_cells(100, 0.5, Geometry(3), 1e12), InputError);
  EXPECT_THROW(field_cells(100, 30, Geometry(3), 1e12), InputError);  // 2 cells
  try {
    field_cells(1000, 1, Geometry(3), 1e9);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--cell = 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace coolgas
