// The two-body rule of rough spheres (Walton 1993; Huthmann & Zippelius,
// PRE 56, R6275 (1997)): with the contact points' relative velocity
// g = v_i - v_j + a (w_i + w_j) x n (a = 1/2, n from i to j), the normal
// part becomes -r g_n and the tangential part -beta g_t; momentum and the
// angular momentum about the contact point are kept; with r = 1 and
// beta = 1 the energy, translational plus rotational, too. beta = -1 leaves
// velocities and spins as the smooth rule does, bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "common/random.h"
#include "simulate/engine/collision_rules.h"
#include "simulate/engine/pair_prediction.h"

namespace coolgas {
namespace {

struct Pair {
  Vec3 vi, vj, wi, wj;
};

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 add(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 scaled(double k, const Vec3& a) { return {k * a.x, k * a.y, k * a.z}; }

// The contact points' relative velocity.
Vec3 contact_velocity(const Pair& p, const Vec3& n) {
  return add(minus(p.vi, p.vj), scaled(0.5, cross(add(p.wi, p.wj), n)));
}
Vec3 tangential(const Vec3& g, const Vec3& n) { return minus(g, scaled(dot(g, n), n)); }

// What the engine does at a contact (engine.cc, collide).
template <class Normal>
Pair collide(const RoughRule<Normal>& rule, Pair p, const Vec3& n) {
  const double g = dot(minus(p.vi, p.vj), n);
  bool below = false;
  const double r = rule.restitution(g, below);
  apply_tangential_restitution(p.vi, p.vj, p.wi, p.wj, n, rule.eta_t, rule.spin_turn);
  apply_restitution(p.vi, p.vj, n, g, r);
  return p;
}

Vec3 gaussian(Random& rng) { return {rng.normal(), rng.normal(), rng.normal()}; }
Vec3 unit(Vec3 v) { return scaled(1.0 / std::sqrt(dot(v, v)), v); }

// A random approaching pair (g_n > 0) with random spins.
Pair random_pair(Random& rng, const Vec3& n) {
  Pair p{gaussian(rng), gaussian(rng), gaussian(rng), gaussian(rng)};
  if (dot(minus(p.vi, p.vj), n) <= 0) std::swap(p.vi, p.vj);
  return p;
}

double energy(const Pair& p, double q) {
  const double inertia = 0.25 * q;  // q a^2 with unit mass
  return 0.5 * (dot(p.vi, p.vi) + dot(p.vj, p.vj)) + 0.5 * inertia * (dot(p.wi, p.wi) + dot(p.wj, p.wj));
}

TEST(RoughCollision, NormalScaledByRTangentialByMinusBeta) {
  Random rng(7);
  for (const double beta : {-0.5, 0.0, 0.4, 1.0})
    for (const double q : {0.4, 2.0 / 3.0, 0.5, 1.0})
      for (int k = 0; k < 100; ++k) {
        const Vec3 n = unit(gaussian(rng));
        const RoughRule<ConstantRestitutionRule> rule({0.7, 0.0}, beta, q);
        const Pair before = random_pair(rng, n), after = collide(rule, before, n);
        const Vec3 g0 = contact_velocity(before, n), g1 = contact_velocity(after, n);
        const double scale = std::sqrt(dot(g0, g0));
        EXPECT_NEAR(dot(g1, n), -0.7 * dot(g0, n), 1e-14 * scale);
        const Vec3 t0 = tangential(g0, n), t1 = tangential(g1, n);
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(t1[d], -beta * t0[d], 1e-14 * scale) << beta << " " << q;
      }
}

// Momentum, and the angular momentum of the pair about the contact point
// (r_i = -a n, r_j = +a n): each impulse acts at that point, so
// I (w_i + w_j) + (-a n) x v_i + (a n) x v_j is kept.
TEST(RoughCollision, MomentumAndAngularMomentumKept) {
  Random rng(8);
  for (int k = 0; k < 200; ++k) {
    const Vec3 n = unit(gaussian(rng));
    const double q = 0.4, inertia = 0.25 * q;
    const RoughRule<ConstantRestitutionRule> rule({0.5, 0.0}, 0.3, q);
    const Pair a = random_pair(rng, n), b = collide(rule, a, n);
    const auto momentum = [](const Pair& p) { return add(p.vi, p.vj); };
    const auto angular = [&](const Pair& p) {
      return add(scaled(inertia, add(p.wi, p.wj)), scaled(0.5, minus(cross(n, p.vj), cross(n, p.vi))));
    };
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(momentum(b)[d], momentum(a)[d], 1e-14);
      EXPECT_NEAR(angular(b)[d], angular(a)[d], 1e-14);
    }
  }
}

// r = 1, beta = 1: the relative contact velocity is reversed whole, and no
// energy is lost (to round-off); any other beta in (-1, 1) loses some.
TEST(RoughCollision, PerfectlyRoughElasticKeepsTheEnergy) {
  Random rng(9);
  for (const double q : {0.4, 2.0 / 3.0, 0.5, 1.0})
    for (int k = 0; k < 200; ++k) {
      const Vec3 n = unit(gaussian(rng));
      const Pair a = random_pair(rng, n);
      const double e0 = energy(a, q);
      EXPECT_NEAR(energy(collide(RoughRule<ElasticRule>({}, 1.0, q), a, n), q), e0, 1e-14 * e0);
      EXPECT_LT(energy(collide(RoughRule<ElasticRule>({}, 0.0, q), a, n), q), e0);
    }
}

// beta = -1: the tangential impulse and the spins' turn are exact zeros, so
// the rough rule gives the smooth rule's velocities bit for bit.
TEST(RoughCollision, BetaMinusOneIsTheSmoothRuleBitForBit) {
  Random rng(10);
  for (int k = 0; k < 500; ++k) {
    const Vec3 n = unit(gaussian(rng));
    const Pair a = random_pair(rng, n);
    const ConstantRestitutionRule smooth{0.6, 0.0};
    const Pair b = collide(RoughRule<ConstantRestitutionRule>(smooth, -1.0, 0.4), a, n);
    Vec3 vi = a.vi, vj = a.vj;
    const double g = dot(minus(vi, vj), n);
    bool below = false;
    apply_restitution(vi, vj, n, g, smooth.restitution(g, below));
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(b.vi[d], vi[d]);
      EXPECT_EQ(b.vj[d], vj[d]);
      EXPECT_EQ(b.wi[d], a.wi[d]);
      EXPECT_EQ(b.wj[d], a.wj[d]);
    }
  }
}

// Disks: velocities in the plane and spins about z stay so, their other
// components exact zeros.
TEST(RoughCollision, DisksStayInThePlane) {
  Random rng(11);
  for (int k = 0; k < 200; ++k) {
    const Vec3 n = unit({rng.normal(), rng.normal(), 0.0});
    Pair a{{rng.normal(), rng.normal(), 0}, {rng.normal(), rng.normal(), 0}, {0, 0, rng.normal()}, {0, 0, rng.normal()}};
    if (dot(minus(a.vi, a.vj), n) <= 0) std::swap(a.vi, a.vj);
    const Pair b = collide(RoughRule<ConstantRestitutionRule>({0.8, 0.0}, 0.5, 0.5), a, n);
    EXPECT_EQ(b.vi.z, 0.0);
    EXPECT_EQ(b.vj.z, 0.0);
    EXPECT_EQ(b.wi.x, 0.0);
    EXPECT_EQ(b.wi.y, 0.0);
    EXPECT_EQ(b.wj.x, 0.0);
    EXPECT_EQ(b.wj.y, 0.0);
    EXPECT_NE(b.wi.z, a.wi.z);
  }
}

}  // namespace
}  // namespace coolgas
