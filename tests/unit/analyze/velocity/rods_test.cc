// Velocity statistics of rods (d = 1) against exact expectations, with fixed
// seeds: in 1D the speed is |vx|, so a Maxwellian's <v⁴>/<v²>² is a
// Gaussian's kurtosis 3 = (d+2)/d, κ = 0 with the delta-method error
// √(24/N) (χ²₁ moments 1, 3, 15, 105; analyze/velocity/distribution.cc);
// Laplace velocities give κ = 24/4 - 3 = 3. Φ pools the one component. The
// tool on a 1D file gives the library's d = 1 numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "analyze/velocity/distribution.h"
#include "common/random.h"
#include "common/tsv.h"
#include "tests/support/run_command.h"
#include "tests/unit/analyze/velocity/velocity_file.h"

namespace coolgas {
namespace {

constexpr std::size_t kRods = 1'000'000;

// 3 numbers per rod, as the frame reader gives them (vy = vz = 0), vx from `draw`.
template <class Draw>
std::vector<double> rod_velocities(std::size_t n, Draw&& draw) {
  std::vector<double> v(3 * n, 0.0);
  for (std::size_t p = 0; p < n; ++p) v[3 * p] = draw();
  return v;
}

std::vector<double> maxwellian_1d(std::uint64_t seed, double sigma, std::size_t n = kRods) {
  Random rng(seed);
  return rod_velocities(n, [&] { return sigma * rng.normal(); });
}

TEST(RodVelocities, MaxwellianKurtosisIsZeroWithTheOneDimensionalError) {
  EXPECT_EQ(maxwellian_speed_ratio(1), 3.0);
  const SpeedMoments m = speed_moments(maxwellian_1d(31, 0.8), Geometry(1));
  const double expected_err = std::sqrt(24.0 / double(kRods));
  EXPECT_NEAR(m.kappa_err, expected_err, 0.03 * expected_err);
  EXPECT_LT(std::abs(m.kappa), 2 * m.kappa_err) << "kappa = " << m.kappa;
  EXPECT_NEAR(m.v_rms, 0.8, 5 * 0.8 / std::sqrt(2.0 * kRods));  // σ of the v_rms estimate = σ/√(2N)
  // Read as disks, the same rods are far from Maxwellian: 3 - 2.
  EXPECT_NEAR(speed_moments(maxwellian_1d(31, 0.8), Geometry(2)).kappa, 1.0, 3 * m.kappa_err);
}

// Laplace velocities of scale b: <v²> = 2b², <v⁴> = 24b⁴: κ = 6 - 3 = 3;
// v_rms = √2 b.
TEST(RodVelocities, LaplaceKurtosisIsThree) {
  Random rng(32);
  auto exponential = [&] { return -0.4 * std::log(1.0 - rng.uniform()); };
  const SpeedMoments m = speed_moments(rod_velocities(kRods, [&] { return exponential() - exponential(); }), Geometry(1));
  EXPECT_LT(std::abs(m.kappa - 3), 3 * m.kappa_err) << "kappa = " << m.kappa << " +- " << m.kappa_err;
  EXPECT_NEAR(m.v_rms, std::sqrt(2.0) * 0.4, 2e-3);
}

// Φ counts N components (vy = vz = 0 are no samples) and is the unit Gaussian.
TEST(RodVelocities, PhiIsTheUnitGaussianOverOneComponent) {
  const auto v = maxwellian_1d(33, 1.3);
  const SpeedMoments m = speed_moments(v, Geometry(1));
  ComponentHistogram h(60, 3.0);
  h.fill(v, m.v_rms, Geometry(1));
  EXPECT_EQ(h.samples(), std::int64_t(kRods));
  for (int j = 0; j < h.bins(); ++j) {  // each bin against the Gaussian's mass in it, within 5 Poisson errors
    const double a = h.center(j) - h.width() / 2, b = a + h.width();
    const double want = double(kRods) * 0.5 * (std::erf(b / std::sqrt(2.0)) - std::erf(a / std::sqrt(2.0)));
    EXPECT_NEAR(double(h.count(j)), want, 5 * std::sqrt(want) + 1) << "bin " << j;
  }
}

// The tool on a 1D file from the real writer: its series row is the library's
// d = 1 statistics, and the table says the dimension.
TEST(RodVelocities, TheToolReadsA1DFile) {
  const std::string path = test::scratch_dir("velocity_rods") + "/run.h5";
  const std::size_t n = 100'000;
  const auto vel = maxwellian_1d(34, 1.0, n);
  const Table t = test::velocity_series_of(path, vel, 2e5, 1);
  ASSERT_EQ(t.rows.size(), 1u);
  const SpeedMoments m = speed_moments(vel, Geometry(1));
  EXPECT_EQ(t.rows[0][t.column("kappa")], m.kappa);
  EXPECT_EQ(t.rows[0][t.column("v_rms")], m.v_rms);
  EXPECT_EQ(t.get("dimension"), "1");
}

}  // namespace
}  // namespace coolgas
