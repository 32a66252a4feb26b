// Velocity-dependent restitution of viscoelastic spheres against its cited
// series (Schwager & Pöschel, PRE 57, 650 (1998): ε = 1 − C1 x + C2 x² ∓ …,
// x = b v^{1/5}, C1 = Γ(3/5)√π / (2^{1/5} 5^{2/5} Γ(21/10)), C2 = (3/5) C1²),
// its limits and monotonicity, and the energy a collision loses with it.
#include <gtest/gtest.h>

#include <cmath>

#include "simulate/engine/collision_rules.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "simulate/engine/pair_prediction.h"
#include "common/random.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

TEST(ViscoelasticRestitution, CoefficientsAreTheClosedForms) {
  const double c1 = std::tgamma(0.6) * std::sqrt(M_PI) / (std::pow(2.0, 0.2) * std::pow(5.0, 0.4) * std::tgamma(2.1));
  EXPECT_NEAR(kViscoelasticC1, c1, 1e-7);
  EXPECT_NEAR(kViscoelasticC1, 1.15344, 1e-5);  // as printed by Schwager & Pöschel
  EXPECT_NEAR(kViscoelasticC2, 0.6 * c1 * c1, 1e-7);
  EXPECT_NEAR(kViscoelasticC2, 0.79826, 1e-5);
}

TEST(ViscoelasticRestitution, ElasticAtZeroSpeed) {
  EXPECT_NEAR(viscoelastic_restitution_exact(0.0), 1.0, 1e-10);
  EXPECT_NEAR(ViscoelasticTable::get()(0.0), 1.0, 1e-10);
}

// The solved equation reproduces the series: the remainder is third order
// (its coefficient, ≈ 0.5, is the next term of the series).
TEST(ViscoelasticRestitution, MatchesTheSeriesToSecondOrder) {
  for (double x : {1e-3, 3e-3, 1e-2, 3e-2}) {
    const double series = 1 - kViscoelasticC1 * x + kViscoelasticC2 * x * x;
    EXPECT_LT(std::fabs(viscoelastic_restitution_exact(x) - series), x * x * x) << "x = " << x;
  }
}

TEST(ViscoelasticRestitution, DecreasesMonotonicallyWithinZeroAndOne) {
  const auto& eps = ViscoelasticTable::get();
  double prev = 1.0 + 1e-12;
  for (double x = 0; x <= ViscoelasticTable::kMaxX; x += 1.0 / 512) {
    const double e = eps(x);
    EXPECT_LT(e, prev) << "x = " << x;
    EXPECT_GT(e, 0.0) << "x = " << x;
    prev = e;
  }
  EXPECT_LE(eps(2 * ViscoelasticTable::kMaxX), eps(ViscoelasticTable::kMaxX));  // held beyond the table
}

TEST(ViscoelasticRestitution, TableInterpolatesTheSolution) {
  Random rng(5);
  for (int k = 0; k < 40; ++k) {
    const double x = rng.uniform() * ViscoelasticTable::kMaxX;
    EXPECT_NEAR(ViscoelasticTable::get()(x), viscoelastic_restitution_exact(x), 1e-7) << "x = " << x;
  }
}

TEST(ViscoelasticRule, RisesToOneAsTheImpactSpeedVanishes) {
  const ViscoelasticRule rule(0.2, 0.0);
  bool below = true;
  double prev = 0;
  for (double g = 10; g > 1e-30; g /= 10) {
    const double r = rule.restitution(g, below);
    EXPECT_FALSE(below);
    EXPECT_GT(r, prev) << "g = " << g;
    prev = r;
  }
  EXPECT_GT(prev, 1 - 1e-6);
  EXPECT_NEAR(rule.restitution(1.0, below), viscoelastic_restitution_exact(0.2), 1e-7);
  // The delta cut-off still applies when asked for.
  EXPECT_EQ(ViscoelasticRule(0.2, 1e-3).restitution(5e-4, below), 1.0);
  EXPECT_TRUE(below);
}

// Two unit masses lose (1 − r²) g² / 4 of kinetic energy, r = ε(b g^{1/5}).
TEST(ViscoelasticRule, EnergyLostPerCollisionMatchesTheFormula) {
  const ViscoelasticRule rule(0.3, 0.0);
  Random rng(9);
  for (int k = 0; k < 100; ++k) {
    Vec3 n{rng.normal(), rng.normal(), rng.normal()};
    const double len = std::sqrt(dot(n, n));
    for (int d = 0; d < 3; ++d) n[d] /= len;
    Vec3 vi{rng.normal(), rng.normal(), rng.normal()}, vj{rng.normal(), rng.normal(), rng.normal()};
    double g = dot(vi, n) - dot(vj, n);
    if (g <= 0) std::swap(vi, vj), g = -g;
    const double e0 = 0.5 * (dot(vi, vi) + dot(vj, vj));
    bool below = false;
    apply_restitution(vi, vj, n, g, rule.restitution(g, below));
    const double r = viscoelastic_restitution_exact(0.3 * std::pow(g, 0.2));
    const double lost = e0 - 0.5 * (dot(vi, vi) + dot(vj, vj));
    EXPECT_NEAR(lost, 0.25 * (1 - r * r) * g * g, 1e-7 * g * g + 1e-13 * e0);
  }
}

TEST(ViscoelasticGas, CoolsWithoutGainingEnergyAndConservesMomentum) {
  Scene s = test::elastic_scene(2000, 0.208, 4);
  s.model = CollisionModel::kViscoelastic;
  s.set_parameter("viscoelastic_b", 0.5);
  auto e = make_engine(s, initial_state(s), 0.0);
  double prev = e->observables().kinetic_energy;
  const double e0 = prev;
  for (double t = 0.5; t <= 20; t += 0.5) {
    e->run_until(t, std::int64_t(1) << 40, nullptr);
    const double now = e->observables().kinetic_energy;
    EXPECT_LE(now, prev * (1 + 1e-14)) << "t = " << t;
    prev = now;
  }
  EXPECT_LT(prev, 0.5 * e0);  // it did cool
  const Vec3 p = e->observables().momentum;
  EXPECT_LT(std::sqrt(dot(p, p)), 1e-11);
}

}  // namespace
}  // namespace coolgas
