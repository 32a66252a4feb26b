// Velocity statistics of disks (d = 2) against exact expectations, with fixed
// seeds: a 2D Maxwellian has κ = <v⁴>/<v²>² - 2 = 0 with the delta-method
// error 2/√N (χ²₂ moments 2, 8, 48, 384; analyze/velocity/distribution.cc)
// and Gaussian components, Φ(y) = e^{-y²/2}/√(2π), as in 3D; Laplace
// components give κ = 3/2 in 2D (1 in 3D). The tool on a 2D file pools the
// two components only.
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/velocity/distribution.h"
#include "common/random.h"
#include "common/tsv.h"
#include "tests/support/run_command.h"
#include "tests/unit/analyze/velocity/velocity_file.h"

namespace coolgas {
namespace {

constexpr std::size_t kDisks = 1'000'000;

// 3 numbers per disk, as the frame reader gives them (vz = 0), x and y from `draw`.
template <class Draw>
std::vector<double> disk_velocities(std::size_t n, Draw&& draw) {
  std::vector<double> v(3 * n, 0.0);
  for (std::size_t p = 0; p < n; ++p) v[3 * p] = draw(), v[3 * p + 1] = draw();
  return v;
}

std::vector<double> maxwellian_2d(std::uint64_t seed, double sigma, std::size_t n = kDisks) {
  Random rng(seed);
  return disk_velocities(n, [&] { return sigma * rng.normal(); });
}

TEST(DiskVelocities, MaxwellianKurtosisIsZeroWithTheTwoDimensionalError) {
  const SpeedMoments m = speed_moments(maxwellian_2d(21, 1.7), Geometry(2));
  const double expected_err = 2.0 / std::sqrt(double(kDisks));
  EXPECT_NEAR(m.kappa_err, expected_err, 0.02 * expected_err);
  EXPECT_LT(std::abs(m.kappa), 2 * m.kappa_err) << "kappa = " << m.kappa;
  EXPECT_NEAR(m.v_rms, 1.7, 5 * 1.7 / std::sqrt(4.0 * kDisks));  // σ of the v_rms estimate ≈ σ/√(4N)
  // Read with the 3D reference the same disks look far from Maxwellian: 2 - 5/3.
  EXPECT_NEAR(speed_moments(maxwellian_2d(21, 1.7), Geometry(3)).kappa, 1.0 / 3.0, 3 * m.kappa_err);
}

// Laplace components of scale b: <x²> = 2b², <x⁴> = 24b⁴; in 2D <v²> = 4b²,
// <v⁴> = 2·24b⁴ + 2·(2b²)² = 56b⁴: κ = 56/16 - 2 = 3/2 exactly.
TEST(DiskVelocities, LaplaceKurtosisIsThreeHalves) {
  Random rng(22);
  auto exponential = [&] { return -0.4 * std::log(1.0 - rng.uniform()); };
  const SpeedMoments m = speed_moments(disk_velocities(kDisks, [&] { return exponential() - exponential(); }), Geometry(2));
  EXPECT_LT(std::abs(m.kappa - 1.5), 3 * m.kappa_err) << "kappa = " << m.kappa << " +- " << m.kappa_err;
  EXPECT_NEAR(m.v_rms, std::sqrt(2.0) * 0.4, 1e-3);
}

// Φ counts 2N components (vz = 0 is no sample) and is the unit Gaussian.
TEST(DiskVelocities, PhiIsTheUnitGaussianOverTwoComponents) {
  const auto v = maxwellian_2d(23, 0.6);
  const SpeedMoments m = speed_moments(v, Geometry(2));
  ComponentHistogram h(80, 4.0);
  h.fill(v, m.v_rms, Geometry(2));
  EXPECT_EQ(h.samples(), std::int64_t(2 * kDisks));
  double integral = 0;
  for (int j = 0; j < h.bins(); ++j) integral += h.phi(j) * h.width();
  EXPECT_NEAR(integral, std::erf(4 / std::sqrt(2.0)), 3e-5);
  for (int j = 0; j < h.bins(); ++j) {  // each bin against the Gaussian's mass in it, within 5 Poisson errors
    const double a = h.center(j) - h.width() / 2, b = a + h.width();
    const double want = 2.0 * kDisks * 0.5 * (std::erf(b / std::sqrt(2.0)) - std::erf(a / std::sqrt(2.0)));
    EXPECT_NEAR(double(h.count(j)), want, 5 * std::sqrt(want) + 1) << "bin " << j;
  }
}

// The tool on a 2D file from the real writer: its series row is the library's
// d = 2 statistics, and the table says the dimension.
TEST(DiskVelocities, TheToolReadsA2DFile) {
  const std::string path = test::scratch_dir("velocity_disks") + "/run.h5";
  const std::size_t n = 100'000;
  const auto vel = maxwellian_2d(24, 1.0, n);
  const Table t = test::velocity_series_of(path, vel, 600, 2);
  ASSERT_EQ(t.rows.size(), 1u);
  const SpeedMoments m = speed_moments(vel, Geometry(2));
  EXPECT_EQ(t.rows[0][t.column("kappa")], m.kappa);
  EXPECT_EQ(t.rows[0][t.column("v_rms")], m.v_rms);
  EXPECT_EQ(t.get("dimension"), "2");
}

}  // namespace
}  // namespace coolgas
