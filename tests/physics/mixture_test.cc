// Mixtures of sizes and masses ([[species]]; tests/physics/README.md) against
// conservation, equipartition and Enskog's collision rates with the mixture
// contact values of common/geometry.h (BMCSL for spheres, Jenkins-Mancini
// for disks).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "simulate/engine/engine.h"
#include "simulate/scene/mixture_rule.h"
#include "simulate/start/initial_state.h"
#include "simulate/start/mixture_enskog.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

constexpr std::int64_t kAllEvents = std::int64_t(1) << 40;
constexpr double kEndless = std::numeric_limits<double>::infinity();

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

// The homogeneous cooling state of an inelastic binary mixture breaks
// equipartition: T_1/T_2 settles at the ratio at which both species cool
// at the same rate (Garzo & Dufty, PRE 60, 5706 (1999)). Their leading
// (Maxwellian) approximation, derived here in d dimensions: with species i,
// j Maxwellian at T_i, T_j, g = v_i - v_j is Gaussian of variance
// w = T_i/m_i + T_j/m_j per component and the centre-of-mass velocity V has
// mean (T_i - T_j)/(M w) g given g (M = m_i + m_j). A collision changes i's
// energy by -m_i mu_ji (1 + r) g_n (V_n + mu_ji (1 - r) g_n / 2), mu_ji =
// m_j/M, and collisions weigh g_n by g_n, so <g_n^2> per collision is 2 w
// in any dimension. Hence, per particle of species i,
//   dE_i/dt = -sum_j nu_ij (1 + r) mu_ji m_i [2 (T_i - T_j)/M + mu_ji (1 - r) w],
// nu_ij Enskog's rate at those temperatures (mixture_enskog.h), and the
// cooling rates zeta_i = -(2/d) (dE_i/dt) / T_i are equal in the cooling
// state. (Garzo & Dufty's Eq. for zeta_i in that approximation, with
// chi_ij = 1 at low density.)
double cooling_rate(const Scene& s, const std::vector<double>& T, std::size_t i, double r) {
  const auto rate = enskog_pair_rates(s, T);
  double dE = 0;
  for (std::size_t j = 0; j < T.size(); ++j) {
    const double mi = s.species_mass(i), mj = s.species_mass(j), M = mi + mj, mu = mj / M;
    const double w = T[i] / mi + T[j] / mj;
    dE -= rate[i][j] * (1 + r) * mu * mi * (2 * (T[i] - T[j]) / M + mu * (1 - r) * w);
  }
  return -dE / T[i];  // the factor 2/d is common to both species
}

// T_1/T_2 at which the two cooling rates agree (bisection: their
// difference changes sign once between 0.1 and 10).
double cooling_state_ratio(const Scene& s, double r) {
  double lo = 0.1, hi = 10;
  const auto gap = [&](double g) { return cooling_rate(s, {g, 1.0}, 0, r) - cooling_rate(s, {g, 1.0}, 1, r); };
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (gap(mid) > 0) == (gap(lo) > 0) ? lo = mid : hi = mid;
  }
  return 0.5 * (lo + hi);
}

// A dilute mixture (phi = 0.02: contact values within 3 % of 1, no
// clustering yet) at r = 0.8 and delta = 0, from equal temperatures at
// t = 0; the ratio sampled at 5, 6, ..., 30 collisions per particle.
// Measured (2026-12-07): 0.8809 against 0.8771 for spheres, 0.9033 against
// 0.9104 for disks, within 1 %. The Maxwellian approximation leaves out
// the Sonine corrections (small for the temperature ratio against DSMC:
// Montanero & Garzo, Granular Matter 4, 17 (2002)), the mean of 26 samples
// scatters by under 1 %: the test allows 3 %.
template <int D>
void expect_cooling_state_ratio(double tolerance) {
  const double r = 0.8;
  const Scene s = test::binary_mixture(test::in_dimension(test::inelastic_scene(4000, 0.02, r, 0.0, 33), D), 0.5, 1.5);
  const Particles p = initial_state(s);
  Engine<MixtureRule<ConstantRestitutionRule>, D> e(p, mixture_rule(s, ConstantRestitutionRule{r, 0.0}), 0.0);
  const Geometry g(D);
  const double per = double(s.N) / 2;  // collisions per particle: 2 C / N
  double sum = 0, sum2 = 0;
  int samples = 0;
  for (double c = 5; c <= 30; c += 1) {
    while (double(e.counters().collisions) < c * per) e.run_until(kEndless, 2000, nullptr);
    const auto T = species_temperatures(e, g);
    sum += T[0] / T[1];
    sum2 += T[0] / T[1] * (T[0] / T[1]);
    ++samples;
  }
  const double mean = sum / samples, spread = std::sqrt(std::max(0.0, sum2 / samples - mean * mean));
  const double theory = cooling_state_ratio(s, r);
  std::printf("%dD, r = %g: T_1/T_2 measured %.4f (spread of one sample %.4f), Garzo-Dufty (Maxwellian) %.4f, "
              "ratio %.4f\n", D, r, mean, spread, theory, mean / theory);
  EXPECT_NEAR(mean / theory, 1.0, tolerance);
  EXPECT_LT(theory, 0.97);  // the heavier species is hotter: a test that equipartition would fail
}

TEST(Mixture, SpheresCoolingStateRatioFollowsGarzoDufty) { expect_cooling_state_ratio<3>(0.03); }
TEST(Mixture, DisksCoolingStateRatioFollowsGarzoDufty) { expect_cooling_state_ratio<2>(0.03); }

}  // namespace
}  // namespace coolgas
