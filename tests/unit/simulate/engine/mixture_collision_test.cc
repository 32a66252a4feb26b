// The two-body rule of a mixture (MixtureRule, pair_prediction.h): particles
// of masses m_i, m_j keep their momentum, the normal relative velocity
// becomes -r times itself, the tangential ones are unchanged, and the energy
// lost is (1 - r^2) mu g^2 / 2 (mu the reduced mass); at equal unit masses
// the rule is the equal spheres' one, bit for bit. Two particles of
// diameters 1 and 1.5 meet at 1.25. Viscoelastic pairs each take their own
// b, b (4 R_ij)^{1/5} (2 m_ij)^{-2/5}.
#include <gtest/gtest.h>

#include <cmath>

#include "common/random.h"
#include "simulate/engine/collision_rules.h"
#include "simulate/engine/engine.h"
#include "simulate/engine/pair_prediction.h"

namespace coolgas {
namespace {

Vec3 random_vector(Random& rng) { return {rng.normal(), rng.normal(), rng.normal()}; }
Vec3 unit(Vec3 a) {
  const double l = std::sqrt(dot(a, a));
  return {a.x / l, a.y / l, a.z / l};
}

TEST(MixtureCollision, KeepsMomentumReversesTheNormalSpeedAndLosesTheReducedMassesEnergy) {
  Random rng(7);
  for (int k = 0; k < 1000; ++k) {
    const double mi = 1.0, mj = 3.375, r = k % 2 ? 1.0 : 0.3 + 0.7 * rng.uniform();
    Vec3 vi = random_vector(rng), vj = random_vector(rng);
    const Vec3 n = unit(random_vector(rng));
    double g = dot(minus(vi, vj), n);
    if (g <= 0) std::swap(vi, vj), g = -g;
    const Vec3 vi0 = vi, vj0 = vj;
    apply_restitution_with_masses(vi, vj, n, g, r, mi, mj);
    const double scale = std::sqrt(dot(vi0, vi0)) + mj * std::sqrt(dot(vj0, vj0));
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(mi * vi[d] + mj * vj[d], mi * vi0[d] + mj * vj0[d], 1e-14 * scale);
    EXPECT_NEAR(dot(minus(vi, vj), n), -r * g, 1e-14 * scale);
    const Vec3 t0 = minus(minus(vi0, vj0), Vec3{g * n.x, g * n.y, g * n.z});
    const double gn = dot(minus(vi, vj), n);
    const Vec3 t1 = minus(minus(vi, vj), Vec3{gn * n.x, gn * n.y, gn * n.z});
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(t1[d], t0[d], 1e-14 * scale);
    const double before = 0.5 * (mi * dot(vi0, vi0) + mj * dot(vj0, vj0));
    const double after = 0.5 * (mi * dot(vi, vi) + mj * dot(vj, vj));
    const double mu = mi * mj / (mi + mj);
    EXPECT_NEAR(before - after, 0.5 * (1 - r * r) * mu * g * g, 1e-13 * before);
  }
}

TEST(MixtureCollision, UnitMassesGiveTheEqualSpheresRuleBitForBit) {
  Random rng(8);
  for (int k = 0; k < 1000; ++k) {
    Vec3 vi = random_vector(rng), vj = random_vector(rng);
    const Vec3 n = unit(random_vector(rng));
    const double g = std::fabs(dot(minus(vi, vj), n)), r = rng.uniform();
    Vec3 ai = vi, aj = vj;
    apply_restitution(vi, vj, n, g, r);
    apply_restitution_with_masses(ai, aj, n, g, r, 1.0, 1.0);
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(ai[d], vi[d]);
      EXPECT_EQ(aj[d], vj[d]);
    }
  }
}

// Particles of species 0 and 1 head on along x, 3 apart, at speeds 1 and -1.
Particles head_on_pair() {
  Particles p;
  p.L = 12;
  p.resize(2);
  p.r = {{3, 6, 6}, {6, 6, 6}};
  p.v = {{1, 0, 0}, {-1, 0, 0}};
  p.species = {0, 1};
  return p;
}

// A unit sphere and one of diameter 1.5 head on along x, 3 apart: they
// touch when their centres are (1 + 1.5)/2 apart, at t = (3 - 1.25)/2, and
// bounce by their masses 1 and 3.375.
TEST(MixtureCollision, TheEngineMeetsAtTheMeanDiameterAndBouncesByTheMasses) {
  const Particles p = head_on_pair();
  const MixtureRule<ElasticRule> rule({}, {1.0, 1.5}, {1.0, 3.375});
  Engine<MixtureRule<ElasticRule>, 3> engine(p, rule, 0.0);
  std::vector<CollisionRecord> log;
  engine.record_collisions(&log);
  engine.run_until(1.0, 100, nullptr);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NEAR(log[0].t, 0.875, 1e-14);
  const EngineFrame f = engine.frame();
  // u_i = ((m_i - m_j) v_i + 2 m_j v_j)/(m_i + m_j), likewise u_j.
  EXPECT_NEAR(f.velocity[0].x, ((1 - 3.375) * 1 + 2 * 3.375 * -1) / 4.375, 1e-14);
  EXPECT_NEAR(f.velocity[1].x, ((3.375 - 1) * -1 + 2 * 1) / 4.375, 1e-14);
  EXPECT_EQ(f.species, (std::vector<std::int32_t>{0, 1}));
  const Observables o = engine.observables();
  EXPECT_NEAR(o.momentum.x, 1 - 3.375, 1e-14);
  EXPECT_NEAR(o.kinetic_energy, 0.5 * (1 + 3.375) / 2, 1e-14);
  ASSERT_EQ(o.species_energy.size(), 2u);
  EXPECT_NEAR(o.species_energy[0], 0.5 * f.velocity[0].x * f.velocity[0].x, 1e-14);  // one particle of each
  EXPECT_NEAR(o.species_energy[1], 0.5 * 3.375 * f.velocity[1].x * f.velocity[1].x, 1e-14);
}

// b scales as R_eff^{1/5} m_eff^{-2/5}: the unit pair keeps b, spheres of
// diameter 2 and mass 8 (R_eff 2 and m_eff 8 times the unit pair's) have
// 2^{1/5} 8^{-2/5} = 1/2 of it, and the pair's order does not matter.
TEST(MixtureCollision, ViscoelasticPairsTakeTheirOwnB) {
  EXPECT_EQ(viscoelastic_pair_b(0.3, 0.5, 0.5, 1, 1), 0.3);
  EXPECT_NEAR(viscoelastic_pair_b(0.3, 1, 1, 8, 8), 0.15, 1e-15);
  EXPECT_EQ(viscoelastic_pair_b(0.3, 0.5, 1, 1, 8), viscoelastic_pair_b(0.3, 1, 0.5, 8, 1));
  // Head on at g = 2, a unit sphere and one of diameter 2, mass 8: the
  // normal relative velocity becomes -eps(b_01 g^{1/5}) g.
  const Particles p = head_on_pair();
  const MixtureRule<ViscoelasticRule> rule({0.3, 0.0}, {1.0, 2.0}, {1.0, 8.0});
  Engine<MixtureRule<ViscoelasticRule>, 3> engine(p, rule, 0.0);
  engine.run_until(2.0, 100, nullptr);
  ASSERT_EQ(engine.counters().collisions, 1);
  const EngineFrame f = engine.frame();
  const double b01 = viscoelastic_pair_b(0.3, 0.5, 1.0, 1.0, 8.0);
  EXPECT_NEAR(f.velocity[1].x - f.velocity[0].x, ViscoelasticTable::get()(b01 * std::pow(2.0, 0.2)) * 2, 1e-14);
  EXPECT_NEAR(f.velocity[0].x + 8 * f.velocity[1].x, 1 - 8, 1e-13);  // momentum kept
  EXPECT_GT(ViscoelasticTable::get()(b01 * std::pow(2.0, 0.2)), ViscoelasticTable::get()(0.3 * std::pow(2.0, 0.2)));
}

}  // namespace
}  // namespace coolgas
