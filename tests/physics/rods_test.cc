// Hard rods on a ring (system.dimension = 1) against exact results and
// conservation laws (tests/physics/README.md; their time unit, Enskog's
// omega with the Tonks gas's g = 1 / (1 - phi), is checked with the other
// dimensions' in collision_rate_test.cc):
//   - the start is the equilibrium hard-rod configuration: the N gaps are
//     the spacings of N uniform points on a ring of length L - N, so their
//     mean is (L - N) / N exactly and their distribution exponential
//     (variance = mean^2 for large N), at any phi < 1;
//   - the temperature is per component: the energy per rod is T / 2;
//   - Haff's law in 1D at early times (derived below);
//   - momentum kept to round-off, and rods never pass each other nor
//     overlap: the ring order of the start is kept, neighbours >= 1 apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

// The ids in ring order: by position at the start (all images 0 then).
std::vector<std::size_t> ring_order(const std::vector<Vec3>& r) {
  std::vector<std::size_t> order(r.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return r[a].x < r[b].x; });
  return order;
}

// The smallest gap between neighbours in the given ring order, of the
// unwrapped positions x + L image (negative: rods overlap or have passed).
double smallest_gap(const EngineFrame& f, const std::vector<std::size_t>& order, double L) {
  const auto x = [&](std::size_t i) { return f.position[i].x + L * double(f.image[i][0]); };
  double gap = x(order.front()) + L - x(order.back()) - 1.0;
  for (std::size_t k = 1; k < order.size(); ++k) gap = std::min(gap, x(order[k]) - x(order[k - 1]) - 1.0);
  return gap;
}

TEST(RodPlacement, IsTheEquilibriumHardRodConfigurationAtAnyDensity) {
  for (const double phi : {0.2, 0.9}) {
    Scene s = test::rod_scene(20000, phi, 51);
    s.equilibrate = 0;
    const Particles p = initial_state(s);
    const auto order = ring_order(p.r);
    std::vector<double> gaps;
    for (std::size_t k = 0; k < order.size(); ++k) {
      const double next = k + 1 < order.size() ? p.r[order[k + 1]].x : p.r[order[0]].x + p.L;
      gaps.push_back(next - p.r[order[k]].x - 1.0);
      ASSERT_EQ(p.r[k].y, 0.0);
      ASSERT_EQ(p.r[k].z, 0.0);
    }
    const double mean = (p.L - double(p.size())) / double(p.size());
    double sum = 0, sum2 = 0;
    for (double g : gaps) sum += g, sum2 += (g - mean) * (g - mean);
    EXPECT_GE(*std::min_element(gaps.begin(), gaps.end()), -1e-9 * p.L) << "phi = " << phi;
    EXPECT_NEAR(sum / double(gaps.size()) / mean, 1.0, 1e-9) << "phi = " << phi;
    // Exponential gaps: variance mean^2 (statistics of 20000: 1.4 %).
    EXPECT_NEAR(sum2 / double(gaps.size()) / (mean * mean), 1.0, 0.05) << "phi = " << phi;
  }
}

TEST(RodTemperature, IsPerComponentAndTheEnergyPerRodIsHalfT) {
  const Scene s = test::rod_scene(10000, 0.3, 52);
  const double T0 = initial_temperature(s);
  EXPECT_DOUBLE_EQ(T0, M_PI * (1 - 0.3) * (1 - 0.3) / (4 * 0.3 * 0.3));  // pi / (2 n g)^2, g = 1/(1 - phi)
  auto e = make_engine(s, initial_state(s), 0.0);
  EXPECT_NEAR(e->observables().kinetic_energy / (0.5 * T0), 1.0, 1e-12);
  for (const Vec3& v : e->frame().velocity) {
    ASSERT_EQ(v.y, 0.0);
    ASSERT_EQ(v.z, 0.0);
  }
}

// Haff's law in 1D. A collision of two unit masses with normal relative
// speed g loses (1 - r^2) g^2 / 4 (reduced mass 1/2). In 1D the normal
// relative velocity is the whole relative velocity, Gaussian of variance
// 2T; weighted by the rate |g| at which such pairs meet,
// <g^2>_coll = <|g|^3> / <|g|> = 2 (2T) = 4T, so a collision loses
// (1 - r^2) T on average. There are N omega / 2 collisions per unit time and
// the energy is N T / 2, so dT/dt = -(1 - r^2) omega T, with omega =
// omega0 sqrt(T / T0) and omega0 = 1 (the time unit):
// T(t) = T0 / (1 + t/t0)^2, t0 = 2 / (1 - r^2) (= 2d / (1 - r^2) in d
// dimensions, as in 2D and 3D), and the collisions per rod up to t are
// t0 ln(1 + t/t0). This assumes molecular chaos, which the 1D gas loses
// (velocities of neighbours become correlated, the energy then decays more
// slowly): the law is checked at early times only, t <= t0/4, within 1 %
// for T and 2 % for the collisions.
TEST(RodHaffLaw, TemperatureAndCollisionsFollowTheHomogeneousCoolingAtEarlyTimes) {
  const double r = 0.98, t0 = 2.0 / (1.0 - r * r);  // t0 about 50
  const Scene s = test::inelastic_rod_scene(10000, 0.1, r, 0.0, 53);
  auto e = make_engine(s, initial_state(s), 0.0);
  const double e0 = e->observables().kinetic_energy;
  for (double t : {0.1 * t0, 0.25 * t0}) {
    e->run_until(t, std::int64_t(1) << 40, nullptr);
    const double haff = 1.0 / ((1 + t / t0) * (1 + t / t0));
    EXPECT_NEAR(e->observables().kinetic_energy / e0 / haff, 1.0, 0.01) << "t = " << t;
    const double per_rod = 2.0 * double(e->counters().collisions) / double(s.N);
    EXPECT_NEAR(per_rod / (t0 * std::log(1 + t / t0)), 1.0, 0.02) << "t = " << t;
  }
}

TEST(RodConservation, MomentumToRoundOffAndRodsNeverPassOrOverlap) {
  // A clustering 1D gas, kept from collapse by the delta cut-off.
  const Scene s = test::inelastic_rod_scene(8000, 0.3, 0.7, 1e-3, 54);
  const Particles start = initial_state(s);
  const auto order = ring_order(start.r);
  auto e = make_engine(s, start, 0.0);
  double speeds = 0;
  for (const Vec3& v : e->frame().velocity) speeds += std::abs(v.x);
  const double e0 = e->observables().kinetic_energy;
  while (e->counters().collisions < 500000) e->run_until(e->now() * 1.2 + 1.0, 1 << 30, nullptr);
  const Vec3 p = e->observables().momentum;
  EXPECT_LT(std::abs(p.x), 1e-12 * speeds);
  EXPECT_EQ(p.y, 0.0);
  EXPECT_EQ(p.z, 0.0);
  EXPECT_LT(e->observables().kinetic_energy, 0.1 * e0);  // it did cool
  const EngineFrame f = e->frame();
  for (std::size_t i = 0; i < f.position.size(); ++i) {
    ASSERT_EQ(f.position[i].y, 0.0) << i;
    ASSERT_EQ(f.position[i].z, 0.0) << i;
    ASSERT_EQ(f.image[i][1], 0) << i;
    ASSERT_EQ(f.image[i][2], 0) << i;
  }
  EXPECT_GT(smallest_gap(f, order, e->box()), -1e-9 * e->box());
}

}  // namespace
}  // namespace coolgas
