// Mixtures of sizes and masses ([[species]]; tests/physics/README.md) against
// conservation, equipartition and Enskog's collision rates with the mixture
// contact values of common/geometry.h (BMCSL for spheres, Jenkins-Mancini
// for disks).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "simulate/engine/engine.h"
#include "simulate/scene/mixture_rule.h"
#include "simulate/start/initial_state.h"
#include "simulate/start/mixture_enskog.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

constexpr std::int64_t kAllEvents = std::int64_t(1) << 40;

// The binary mixture of the checks: half unit spheres (mass 1), half of
// diameter 1.5 (mass 1.5^3 = 3.375; disks: 1.5^2 = 2.25), phi = 0.2.
template <int D>
Scene mixture_scene(std::int64_t N, std::int64_t seed) {
  Scene s = test::binary_mixture(test::in_dimension(test::elastic_scene(N, 0.2, seed), D), 0.5, 1.5);
  return s;
}

// Each species' temperature per axis, T_k = 2 E_k / d.
std::vector<double> species_temperatures(const EngineBase& e, Geometry g) {
  std::vector<double> T = e.observables().species_energy;
  for (double& t : T) t /= g.energy_per_temperature();
  return T;
}

// The start heated unevenly: the second species' velocities (their own mean
// removed from each species, so the total momentum stays 0) scaled by √3,
// T_2 = 3 T_1 at t = 0. Elastic collisions must bring T_2/T_1 to 1.
template <int D>
void expect_equipartition() {
  const Scene s = mixture_scene<D>(2000, 31);
  Particles p = initial_state(s);
  for (std::uint8_t k = 0; k < 2; ++k) {
    Vec3 mean;
    double n = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.species[i] == k) n += 1, mean = {mean.x + p.v[i].x, mean.y + p.v[i].y, mean.z + p.v[i].z};
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.species[i] == k)
        for (int d = 0; d < D; ++d) p.v[i][d] = (p.v[i][d] - mean[d] / n) * (k == 1 ? std::sqrt(3.0) : 1.0);
  }
  Engine<MixtureRule<ElasticRule>, D> e(p, mixture_rule(s, ElasticRule{}), 0.0);
  const Geometry g(D);
  const Observables first = e.observables();
  const auto T0 = species_temperatures(e, g);
  EXPECT_NEAR(T0[1] / T0[0], 3.0, 0.3);
  // Relaxation takes a few collision times; then the ratio is averaged over
  // 30 samples one collision time apart.
  e.run_until(10, kAllEvents, nullptr);
  double sum = 0, sum2 = 0;
  const int samples = 30;
  for (int k = 1; k <= samples; ++k) {
    e.run_until(10 + k, kAllEvents, nullptr);
    const auto T = species_temperatures(e, g);
    sum += T[1] / T[0];
    sum2 += T[1] / T[0] * (T[1] / T[0]);
    const Observables o = e.observables();
    ASSERT_NEAR(o.kinetic_energy, first.kinetic_energy, 1e-12 * first.kinetic_energy);
    for (int d = 0; d < 3; ++d) ASSERT_NEAR(o.momentum[d], 0.0, 1e-11);
  }
  const double mean = sum / samples, spread = std::sqrt(std::max(0.0, sum2 / samples - mean * mean));
  std::printf("%dD: T_2/T_1 = %.4f (spread of one sample %.4f, t = 11..40)\n", D, mean, spread);
  // One sample's ratio scatters by about sqrt(2/(d N_1) + 2/(d N_2)): 4.5 %
  // in 3D, 5.5 % in 2D; the mean of 30 (collision times apart, nearly
  // independent) by about a fifth of that. 3 % is three of those or more.
  EXPECT_NEAR(mean, 1.0, 0.03);
  EXPECT_LT(spread, 0.1);
}

TEST(Mixture, ElasticSpheresEquipartition) { expect_equipartition<3>(); }
TEST(Mixture, ElasticDisksEquipartition) { expect_equipartition<2>(); }

// In equilibrium Enskog's rates are exact but for the contact value, so the
// measured collisions of each species pair, per particle per unit time,
// test the mixture contact value (and the time unit: the mean rate is 1 at
// T0). 4000 particles from t = 2 to 12 make about 10^4 collisions of each
// pair (1 % Poisson noise).
template <int D>
void expect_enskog_pair_rates(double tolerance) {
  const Scene s = mixture_scene<D>(4000, 32);
  const Particles p = initial_state(s);
  Engine<MixtureRule<ElasticRule>, D> e(p, mixture_rule(s, ElasticRule{}), 0.0);
  e.run_until(2, kAllEvents, nullptr);
  std::vector<CollisionRecord> log;
  e.record_collisions(&log);
  const double span = 10;
  e.run_until(2 + span, kAllEvents, nullptr);
  double count[2][2] = {};
  for (const CollisionRecord& c : log) {
    const int a = p.species[std::size_t(c.i)], b = p.species[std::size_t(c.j)];
    count[a][b] += 1, count[b][a] += a != b;
  }
  const auto n = s.species_counts();
  const double T = initial_temperature(s);
  const auto rate = enskog_pair_rates(s, {T, T});
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      // a pair of one species counts once per collision, for two particles
      const double measured = count[a][b] * (a == b ? 2.0 : 1.0) / (double(n[std::size_t(a)]) * span);
      std::printf("%dD: nu_%d%d measured %.4f, Enskog (%s) %.4f, ratio %.4f\n", D, a + 1, b + 1, measured,
                  Geometry(D).mixture_contact_value_name(), rate[a][b], measured / rate[a][b]);
      EXPECT_NEAR(measured / rate[std::size_t(a)][std::size_t(b)], 1.0, tolerance);
    }
  EXPECT_NEAR(enskog_mean_rate(s, T), 1.0, 1e-12);  // T0 makes the mean Enskog rate the time unit
}

TEST(Mixture, SpherePairRatesFollowEnskogWithBmcsl) { expect_enskog_pair_rates<3>(0.03); }
TEST(Mixture, DiskPairRatesFollowEnskogWithJenkinsMancini) { expect_enskog_pair_rates<2>(0.03); }

}  // namespace
}  // namespace coolgas
