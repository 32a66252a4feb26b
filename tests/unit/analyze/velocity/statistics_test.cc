// Velocity statistics against exact expectations, on synthetic samples with
// fixed seeds: Gaussian components (a Maxwellian) and Laplace components
// (an exponential distribution, Φ(y) = e^{-√2|y|}/√2 at unit variance).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analyze/velocity/distribution.h"
#include "analyze/velocity/tail.h"
#include "analyze/velocity/tool.h"
#include "common/error.h"
#include "common/trajectory/h5md_writer.h"
#include "common/random.h"
#include "common/tsv.h"
#include "tests/support/run_command.h"
#include "tests/unit/analyze/velocity/velocity_file.h"

namespace coolgas {
namespace {

constexpr std::size_t kParticles = 1'000'000;

// Samples from the portable generator (common/random.h): the same numbers on every platform.
std::vector<double> gaussian(std::uint64_t seed, double sigma = 1.0) {
  Random rng(seed);
  std::vector<double> v(3 * kParticles);
  for (double& x : v) x = sigma * rng.normal();
  return v;
}

// Laplace with scale b: the difference of two exponentials of mean b (-b ln U, U uniform in (0, 1]).
std::vector<double> laplace(std::uint64_t seed, double b) {
  Random rng(seed);
  auto exponential = [&] { return -b * std::log(1.0 - rng.uniform()); };
  std::vector<double> v(3 * kParticles);
  for (double& x : v) x = exponential() - exponential();
  return v;
}

// Maxwellian: κ = 0 (tests/physics/README.md), and the delta-method standard error
// is sqrt(40 / (27 N)) (from the χ²₃ moments 3, 15, 105, 945; derivation in
// analyze/velocity/distribution.cc).
TEST(SpeedMoments, GaussianKurtosisIsZeroWithinItsStandardError) {
  const SpeedMoments m = speed_moments(gaussian(11, 2.5), Geometry(3));
  const double expected_err = std::sqrt(40.0 / (27.0 * kParticles));
  EXPECT_NEAR(m.kappa_err, expected_err, 0.02 * expected_err);
  EXPECT_LT(std::abs(m.kappa), 2 * m.kappa_err) << "kappa = " << m.kappa;
  EXPECT_NEAR(m.v_rms, 2.5, 5 * 2.5 / std::sqrt(6.0 * kParticles));  // σ of the v_rms estimate ≈ σ/√(6N)
}

// Laplace components of scale b: <x²> = 2b², <x⁴> = 24b⁴, so for the speed
// <v²> = 6b² and <v⁴> = 3·24b⁴ + 6·(2b²)² = 96b⁴: κ = 96/36 - 5/3 = 1 exactly.
TEST(SpeedMoments, LaplaceKurtosisIsOne) {
  const SpeedMoments m = speed_moments(laplace(12, 0.3), Geometry(3));
  EXPECT_LT(std::abs(m.kappa - 1.0), 3 * m.kappa_err) << "kappa = " << m.kappa << " +- " << m.kappa_err;
  EXPECT_NEAR(m.v_rms, std::sqrt(2.0) * 0.3, 1e-3);
}

TEST(ComponentHistogram, IntegratesToTheFractionInsideTheRange) {
  const auto v = gaussian(13);
  const SpeedMoments m = speed_moments(v, Geometry(3));
  ComponentHistogram h(80, 4.0);
  h.fill(v, m.v_rms, Geometry(3));
  double integral = 0;
  for (int j = 0; j < h.bins(); ++j) integral += h.phi(j) * h.width();
  // P(|y| < 4) for a unit Gaussian = erf(4/√2) = 0.99993666 (exact), up to sampling noise.
  EXPECT_NEAR(integral, std::erf(4 / std::sqrt(2.0)), 2e-5);
  // Φ(0) = 1/√(2π) = 0.39894; the centre bins average over ±0.05, lowering Φ by ~0.04 %.
  EXPECT_NEAR(0.5 * (h.phi(39) + h.phi(40)), 1 / std::sqrt(2 * M_PI), 0.003);
}

// A tail that is exactly -ln Φ = c y^β gives back β and c, whatever the weights.
TEST(TailFit, RecoversAnExactStretchedExponential) {
  std::vector<TailPoint> pts;
  for (double y = 1.5; y < 5; y += 0.25) pts.push_back({y, std::exp(-0.8 * std::pow(y, 5.0 / 3.0)), 100 + 10 * y});
  const auto fit = fit_tail(pts);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->beta, 5.0 / 3.0, 1e-12);
  EXPECT_NEAR(fit->prefactor, 0.8, 1e-12);
  EXPECT_FALSE(fit_tail({pts[0], pts[1]}));  // two points cannot give an error
}

// The β that the fit gives for the exact distribution binned like the sample:
// the expected count of each folded bin is 3N·P(a < |y| < b).
double expected_beta(const ComponentHistogram& h, double y_from, double min_count, double (*prob)(double, double)) {
  std::vector<TailPoint> pts;
  for (int j = h.bins() / 2; j < h.bins(); ++j) {
    const double a = h.center(j) - h.width() / 2, b = a + h.width();
    const double count = 3.0 * kParticles * prob(a, b);
    if (h.center(j) >= y_from && count >= min_count)
      pts.push_back({h.center(j), count / (6.0 * kParticles * h.width()), count});
  }
  return fit_tail(pts)->beta;
}

double gaussian_prob(double a, double b) { return std::erf(b / std::sqrt(2.0)) - std::erf(a / std::sqrt(2.0)); }
double laplace_prob(double a, double b) { return std::exp(-std::sqrt(2.0) * a) - std::exp(-std::sqrt(2.0) * b); }

// For a Gaussian -ln Φ = y²/2 + ln√(2π), so β → 2 only as y → ∞; over
// 1.5 <= y <~ 4.3 the exact local exponent is 1.4-1.8. The sample's β must
// match the exact distribution's β for the same bins within its error.
TEST(TailFit, GaussianTailMatchesTheExactExpectation) {
  const auto v = gaussian(14);
  ComponentHistogram h(120, 6.0);
  h.fill(v, speed_moments(v, Geometry(3)).v_rms, Geometry(3));
  const auto fit = fit_tail(tail_points(h, 1.5, 25));
  ASSERT_TRUE(fit);
  const double want = expected_beta(h, 1.5, 25, gaussian_prob);
  EXPECT_GT(want, 1.4);
  EXPECT_LT(want, 2.0);
  EXPECT_NEAR(fit->beta, want, 3 * fit->beta_err) << "beta = " << fit->beta << " +- " << fit->beta_err;
  EXPECT_LT(fit->beta_err, 0.05);
}

// For the exponential -ln Φ = √2 y + ln √2: β → 1 from below.
TEST(TailFit, ExponentialTailMatchesTheExactExpectation) {
  const auto v = laplace(15, 1.0);
  ComponentHistogram h(120, 12.0);
  h.fill(v, speed_moments(v, Geometry(3)).v_rms, Geometry(3));
  const auto fit = fit_tail(tail_points(h, 1.5, 25));
  ASSERT_TRUE(fit);
  const double want = expected_beta(h, 1.5, 25, laplace_prob);
  EXPECT_GT(want, 0.85);
  EXPECT_LT(want, 1.0);
  EXPECT_NEAR(fit->beta, want, 3 * fit->beta_err) << "beta = " << fit->beta << " +- " << fit->beta_err;
}

TEST(ComponentHistogram, RejectsBadBins) {
  EXPECT_THROW(ComponentHistogram(7, 5.0), InputError);
  EXPECT_THROW(ComponentHistogram(0, 5.0), InputError);
  EXPECT_THROW(ComponentHistogram(10, 0.0), InputError);
  EXPECT_THROW(speed_moments(std::vector<double>(6, 0.0), Geometry(3)), InputError);  // v_rms = 0
}

// The tool end to end on a file from the real writer: the series row carries
// the same κ and β as the library computes directly.
TEST(VelocityTool, SeriesRowMatchesTheLibrary) {
  const std::string path = test::scratch_dir("velocity_tool") + "/run.h5";
  const std::size_t n = 200'000;
  Random rng(16);
  std::vector<double> vel(3 * n);
  for (double& x : vel) x = rng.normal();
  const Table t = test::velocity_series_of(path, vel, 100, 3);
  ASSERT_EQ(t.rows.size(), 1u);
  const VelocityOptions o;
  const SpeedMoments m = speed_moments(vel, Geometry(3));
  ComponentHistogram h(o.bins, o.ymax);
  h.fill(vel, m.v_rms, Geometry(3));
  const auto fit = fit_tail(tail_points(h, o.tail_from, o.min_count));
  EXPECT_EQ(t.rows[0][t.column("t")], 5.0);
  EXPECT_EQ(t.rows[0][t.column("kappa")], m.kappa);
  EXPECT_EQ(t.rows[0][t.column("beta")], fit->beta);
  EXPECT_EQ(t.get("table"), "series");
}

}  // namespace
}  // namespace coolgas
