// The driven gas (simulate/engine/driving.h) against kinetic theory
// (tests/physics/README.md, "Driven gas"): the white-noise thermostat's
// steady state (van Noije & Ernst, Granular Matter 1, 57 (1998)) is reached
// and stays; its temperature is the one at which the collisions lose what
// the kicks bring in, P = (1 − r²) ω_E(T) T (1 + 3 a2/16) / 2 per particle;
// its a2 is van Noije & Ernst's; and at δ = 0 eight times the power gives
// four times the temperature (T ∝ P^(2/3)).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

// a2 of the white-noise thermostat's steady state, first Sonine
// approximation (van Noije & Ernst 1998, Eq. (4.13) with the noise term).
double a2_white_noise(double r, int d) {
  return 16 * (1 - r) * (1 - 2 * r * r) / (73 + 56 * d - 24 * d * r - 105 * r + 30 * (1 - r) * r * r);
}

// The steady temperature of power P (m σ² ω0³, the engine's unit): the root of P = (1 − r²) ω_E(T) T (1 + 3 a2/16) / 2, ω_E ∝ √T.
double steady_temperature(const Scene& s, double power, double r) {
  const Geometry g = s.geometry();
  const double n = double(s.N) / g.box_measure(s.L), rate_at_1 = g.enskog_rate(n, s.phi, 1.0);
  const double loss = (1 - r * r) * rate_at_1 * (1 + 3 * a2_white_noise(r, g.d()) / 16) / 2;  // P = loss T^(3/2)
  return std::pow(power / loss, 2.0 / 3.0);
}

// Means of blocks of consecutive samples, and their standard error.
struct Mean {
  double value, error;
};
Mean block_mean(const std::vector<double>& x, int blocks) {
  const std::size_t per = x.size() / std::size_t(blocks);
  std::vector<double> means;
  for (int b = 0; b < blocks; ++b)
    means.push_back(std::accumulate(x.begin() + long(b * per), x.begin() + long((b + 1) * per), 0.0) / double(per));
  const double m = std::accumulate(means.begin(), means.end(), 0.0) / blocks;
  double var = 0;
  for (double y : means) var += (y - m) * (y - m);
  return {m, std::sqrt(var / (blocks - 1) / blocks)};
}

// T and a2 sampled every `every` time units from t_relax to t_end.
struct Samples {
  std::vector<double> T, a2;
};
Samples steady_samples(const Scene& s, double t_relax, double t_end, double every) {
  auto e = make_engine(s, initial_state(s), 0.0);
  const double d = s.geometry().d();
  Samples out;
  for (double t = t_relax; t <= t_end; t += every) {
    e->run_until(t, std::int64_t(1) << 40, nullptr);
    double v2 = 0, v4 = 0;
    for (const Vec3& v : e->frame().velocity) {
      const double c2 = dot(v, v);
      v2 += c2;
      v4 += c2 * c2;
    }
    v2 /= double(s.N);
    v4 /= double(s.N);
    out.T.push_back(v2 / d);
    out.a2.push_back(d / (d + 2) * v4 / (v2 * v2) - 1);
  }
  return out;
}

Scene driven_scene(double r, double power, std::int64_t seed) {
  Scene s = test::inelastic_scene(1000, 0.05, r, 0.0, seed);
  s.driving_power = power;
  return s;
}

// r = 0.5 (a2 = 0.0256 in 3D), the power that holds the gas near T0 (so one
// time unit is about one collision time), 20 collision times to relax (a2
// relaxes within a few, T within 1/ζ = 4), then 600 sampled every 2.
// The steady state: both halves of the run at the same T within 4 standard
// errors (block means of 10 blocks); that T within 4 % of the energy balance
// of Enskog theory: measured 2.5 % above it (1.7 % with kicks 4 times as
// frequent, 0.8 % and 1.2 % at r = 0.8; sampling errors 0.3-0.5 %, the
// Enskog rate at phi = 0.05 within 1 % of the measured one,
// collision_rate_test.cc), an excess that grows with the inelasticity as
// the velocity correlations molecular chaos leaves out do; the kicks'
// discretisation lowers the mean T by about ε²/48 (ε = 0.125, the relative
// jump of T at a kick: docs/simulate.md). A factor 2 or d amiss in the
// kicks' variance is far outside. a2 within 4 standard errors plus
// 10 % of van Noije & Ernst's (the first Sonine approximation: the second
// Sonine coefficient changes a2 of the white-noise state by a few per cent at
// r = 0.5, Montanero & Santos, Granular Matter 2, 53 (2000)).
TEST(DrivenGas, ReachesTheWhiteNoiseSteadyStateOfKineticTheory) {
  const double r = 0.5;
  const double power = (1 - r * r) / 2;  // in T0 per collision time, the scene's unit
  const Scene s = driven_scene(r, power, 7);
  const double T0 = initial_temperature(s);
  const Samples x = steady_samples(s, 20, 620, 2);
  const std::size_t half = x.T.size() / 2;
  const Mean first = block_mean({x.T.begin(), x.T.begin() + long(half)}, 10);
  const Mean second = block_mean({x.T.begin() + long(half), x.T.end()}, 10);
  EXPECT_NEAR(first.value, second.value, 4 * std::hypot(first.error, second.error)) << "not steady";
  const Mean T = block_mean(x.T, 10), a2 = block_mean(x.a2, 10);
  const double theory = steady_temperature(s, power * T0, r);  // in the engine's units
  EXPECT_NEAR(T.value / theory, 1.0, 0.04) << "T = " << T.value << " ± " << T.error << ", theory " << theory;
  const double a2_theory = a2_white_noise(r, 3);
  EXPECT_NEAR(a2.value, a2_theory, 4 * a2.error + 0.1 * a2_theory) << "a2 = " << a2.value << " ± " << a2.error;
  RecordProperty("T_over_theory", std::to_string(T.value / theory));
  RecordProperty("a2", std::to_string(a2.value) + " +- " + std::to_string(a2.error));
}

// At δ = 0 the steady temperature scales as P^(2/3): 8 times the power, 4
// times the temperature, within 4 standard errors of the ratio (both runs
// start at the same T0, so one heats and one cools into its steady state;
// the bit-for-bit form of the symmetry is tests/unit/simulate/engine/driving_test.cc).
TEST(DrivenGas, EightTimesThePowerFourTimesTheTemperature) {
  const double r = 0.7;
  const double power = 0.1;
  // The slower gas (T about T0/2, 1/ζ about 8 time units) relaxes for 50
  // and is sampled for 300; the faster one, whose times are half as long, for half as long.
  const Samples slow = steady_samples(driven_scene(r, power, 8), 50, 350, 2);
  const Samples fast = steady_samples(driven_scene(r, 8 * power, 9), 25, 175, 1);
  const Mean a = block_mean(slow.T, 10), b = block_mean(fast.T, 10);
  const double ratio = b.value / a.value;
  EXPECT_NEAR(ratio, 4.0, 4 * ratio * std::hypot(a.error / a.value, b.error / b.value)) << "T = " << a.value << ", " << b.value;
}

}  // namespace
}  // namespace coolgas
