// The two-body rule, the paper's Eq. (1): momentum conserved exactly, the
// normal relative velocity reversed and scaled by r, the tangential one
// unchanged; r = r0 above the cut-off delta and 1 below it (Ben-Naim et al.,
// PRL 83, 4069 (1999), as used by the paper).
#include <gtest/gtest.h>

#include <cmath>

#include "simulate/engine/collision_rules.h"
#include "simulate/engine/pair_prediction.h"
#include "common/random.h"

namespace coolgas {
namespace {

struct Outcome {
  Vec3 vi, vj;
  bool below;
};

// Collides two spheres with normal n (i -> j) using the rule; returns velocities after.
template <class Rule>
Outcome collide(const Rule& rule, Vec3 vi, Vec3 vj, const Vec3& n) {
  const double g = (vi.x - vj.x) * n.x + (vi.y - vj.y) * n.y + (vi.z - vj.z) * n.z;
  bool below = false;
  apply_restitution(vi, vj, n, g, rule.restitution(g, below));
  return {vi, vj, below};
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

TEST(CollisionRule, NormalScaledByRTangentialKeptMomentumExact) {
  const double s = 1.0 / std::sqrt(3.0);
  const Vec3 n{s, s, s};
  // Values chosen so that every sum below is exact in binary floating point.
  const Vec3 ui{1.5, 0.25, -0.75}, uj{-0.5, 0.5, 0.125};
  const ConstantRestitutionRule rule{0.5, 1e-4};
  const Outcome o = collide(rule, ui, uj, n);
  const Vec3 g0 = sub(ui, uj), g1 = sub(o.vi, o.vj);
  EXPECT_NEAR(dot(g1, n), -0.5 * dot(g0, n), 1e-15);
  const Vec3 t0 = sub(g0, {dot(g0, n) * n.x, dot(g0, n) * n.y, dot(g0, n) * n.z});
  const Vec3 t1 = sub(g1, {dot(g1, n) * n.x, dot(g1, n) * n.y, dot(g1, n) * n.z});
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(t1[d], t0[d], 1e-15);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(o.vi[d] + o.vj[d], ui[d] + uj[d], 1e-15);
  EXPECT_FALSE(o.below);
}

TEST(CollisionRule, AxisAlignedCollisionConservesMomentumBitForBit) {
  const Vec3 n{1, 0, 0};
  const Outcome o = collide(ConstantRestitutionRule{0.25, 0.0}, {1.0, 0.5, 0}, {-1.0, 0, 0.5}, n);
  EXPECT_EQ(o.vi.x + o.vj.x, 0.0);  // 1 - 1.25 and -1 + 1.25: exact
  EXPECT_EQ(o.vi.x, -0.25);         // g = 2, normal part -> -r g = -0.5, shared equally
  EXPECT_EQ(o.vj.x, 0.25);
  EXPECT_EQ(o.vi.y, 0.5);           // tangential unchanged
  EXPECT_EQ(o.vj.z, 0.5);
}

TEST(CollisionRule, ElasticBelowTheCutOffInelasticAbove) {
  const ConstantRestitutionRule rule{0.1, 1e-3};
  const Vec3 n{1, 0, 0};
  // Normal relative speed 0.9e-3 < delta: elastic, the relative velocity just reverses.
  Outcome slow = collide(rule, {0.45e-3, 0, 0}, {-0.45e-3, 0, 0}, n);
  EXPECT_TRUE(slow.below);
  EXPECT_NEAR(slow.vi.x - slow.vj.x, -0.9e-3, 1e-18);
  // 1.1e-3 > delta: scaled by r0.
  Outcome fast = collide(rule, {0.55e-3, 0, 0}, {-0.55e-3, 0, 0}, n);
  EXPECT_FALSE(fast.below);
  EXPECT_NEAR(fast.vi.x - fast.vj.x, -0.1 * 1.1e-3, 1e-18);
}

TEST(CollisionRule, ElasticRuleKeepsEnergy) {
  const double s = 1.0 / std::sqrt(2.0);
  const Vec3 ui{0.3, -0.2, 0.7}, uj{-0.6, 0.1, 0.2};
  const Outcome o = collide(ElasticRule{}, ui, uj, {s, 0, s});
  EXPECT_NEAR(dot(o.vi, o.vi) + dot(o.vj, o.vj), dot(ui, ui) + dot(uj, uj), 1e-15);
}

TEST(PairPrediction, ContactTimeOfAHeadOnApproach) {
  // Centres 3 apart closing at speed 2: contact (distance 1) after exactly 1.
  EXPECT_DOUBLE_EQ(time_to_contact({3, 0, 0}, {-2, 0, 0}), 1.0);
  EXPECT_EQ(time_to_contact({3, 0, 0}, {2, 0, 0}), kNever);      // receding
  EXPECT_EQ(time_to_contact({3, 2, 0}, {-1, 0, 0}), kNever);     // miss: impact parameter 2 > 1
  EXPECT_EQ(time_to_contact({0.999, 0, 0}, {-1, 0, 0}), 0.0);    // overlapping and approaching: now
  EXPECT_EQ(time_to_contact({0.999, 0, 0}, {1, 0, 0}), kNever);  // overlapping but separating
}

TEST(PairPrediction, TheEarlyExitNeverChangesAnEarlierContact) {
  // The engine's filtered search must pick exactly what the plain formula
  // picks: equal whenever the contact is earlier than the limit.
  Random rng(5);
  int earlier = 0;
  for (int k = 0; k < 200000; ++k) {
    const Vec3 dr{4 * rng.uniform() - 2, 4 * rng.uniform() - 2, 4 * rng.uniform() - 2};
    const Vec3 dv{2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1};
    const double limit = 3 * rng.uniform();
    const double plain = time_to_contact(dr, dv), filtered = time_to_contact_before(dr, dv, limit);
    if (plain < limit) {
      ASSERT_EQ(filtered, plain);
      ++earlier;
    } else {
      ASSERT_TRUE(filtered == kNever || filtered >= limit);
    }
  }
  EXPECT_GT(earlier, 1000);  // the comparison was exercised
}

}  // namespace
}  // namespace coolgas
