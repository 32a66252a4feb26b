// Every engine against a slow, plainly correct reference, in one typed test
// body: the three rules of Engine<Rule, D> in 3D, 2D and 1D, rough spheres
// and disks, mixtures (elastic, inelastic, viscoelastic) in 3D, 2D and 1D (cells, calendar,
// lazy positions) against the all-pairs reference engine, and the aggregation engine (chains,
// a grid that is rebuilt as aggregates grow) against the all-pairs
// aggregation reference, from equal spheres and from a mixture. Chaos amplifies round-off differences, so only the
// first few events per particle are compared.
#include <gtest/gtest.h>

#include <memory>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/engine/engine.h"
#include "simulate/engine/reference_engine.h"
#include "simulate/scene/mixture_rule.h"
#include "simulate/start/initial_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

// A case: a start, the fast engine on it, the reference's sequence, and how
// many events to compare.
template <class Rule, int D = 3>
struct RuleCase {
  using EngineType = Engine<Rule, D>;
  static std::unique_ptr<EngineType> engine(const Particles& p, const Rule& rule) {
    return std::make_unique<EngineType>(p, rule, 0.0);
  }
  static std::vector<CollisionRecord> reference(const Particles& p, const Rule& rule, int n) {
    return reference_collisions(p, rule, 0.0, 1e9, n);
  }
};

// Each case in 3D and, the same N, phi and seed, as disks (D = 2: one layer
// of cells, 9 around each) and as rods on a ring (D = 1: one row of cells, 3
// around each; phi the line fraction); the reference needs no other
// version, it works on 3-vectors whose z (and y) stay 0.
template <int D>
struct Elastic : RuleCase<ElasticRule, D> {
  static Scene scene() { return test::in_dimension(test::elastic_scene(120, 0.15, 3), D); }
  static ElasticRule rule() { return {}; }
  static constexpr int kEvents = 300;
};
template <int D>
struct DenseElastic : RuleCase<ElasticRule, D> {
  static Scene scene() { return test::in_dimension(test::elastic_scene(200, 0.35, 5), D); }
  static ElasticRule rule() { return {}; }
  static constexpr int kEvents = 400;
};
// phi = 0.02: one-diameter cells would be 24 per particle, so the engine's
// cells are one mean spacing wide (cell_width, engine.cc: 10 per side of
// L = 29.7, 2.97 wide; disks: 6.3 wide in a square of side 198). The box is
// large enough that free flights (mean 5.9; disks 14) stay well below L/2,
// as the reference's minimum-image predictions need (rods: cells 50 wide on
// a ring of 50000, free flights of 49).
template <int D>
struct DiluteElastic : RuleCase<ElasticRule, D> {
  static Scene scene() { return test::in_dimension(test::elastic_scene(1000, 0.02, 8), D); }
  static ElasticRule rule() { return {}; }
  static constexpr int kEvents = 600;
};
template <int D>
struct Inelastic : RuleCase<ConstantRestitutionRule, D> {
  static Scene scene() { return test::in_dimension(test::inelastic_scene(120, 0.15, 0.5, 1e-3, 4), D); }
  static ConstantRestitutionRule rule() { return {0.5, 1e-3}; }
  static constexpr int kEvents = 300;
};
template <int D>
struct Viscoelastic : RuleCase<ViscoelasticRule, D> {
  static Scene scene() { return test::in_dimension(test::elastic_scene(120, 0.15, 6), D); }
  static ViscoelasticRule rule() { return {0.3, 0.0}; }
  static constexpr int kEvents = 300;
};

// Rough particles (RoughRule): a collision turns both spins, and the spins
// turn the velocities of later collisions, so the events follow the
// reference's only if both engines apply the same tangential rule (and the
// fast one keeps each spin with its particle through renumbering). Inelastic
// with beta = 0.4, and perfectly rough elastic ones (beta = 1) in a thin
// shell's inertia.
template <int D>
struct Rough : RuleCase<RoughRule<ConstantRestitutionRule>, D> {
  static Scene scene() {
    return test::in_dimension(test::rough(test::inelastic_scene(120, 0.15, 0.7, 1e-3, 10), 0.4), D);
  }
  static RoughRule<ConstantRestitutionRule> rule() { return {{0.7, 1e-3}, 0.4, Geometry(D).uniform_inertia()}; }
  static constexpr int kEvents = 300;
};
template <int D>
struct PerfectlyRough : RuleCase<RoughRule<ElasticRule>, D> {
  static Scene scene() {
    return test::in_dimension(test::rough(test::elastic_scene(120, 0.15, 11), 1.0, Geometry(D).largest_inertia()), D);
  }
  static RoughRule<ElasticRule> rule() { return {{}, 1.0, Geometry(D).largest_inertia()}; }
  static constexpr int kEvents = 300;
};

// Viscoelastic rough spheres: the impact speed's restitution beside beta.
template <int D>
struct RoughViscoelastic : RuleCase<RoughRule<ViscoelasticRule>, D> {
  static Scene scene() { return test::in_dimension(test::rough(test::elastic_scene(120, 0.15, 15), 0.2), D); }
  static RoughRule<ViscoelasticRule> rule() { return {{0.3, 0.0}, 0.2, Geometry(D).uniform_inertia()}; }
  static constexpr int kEvents = 300;
};

// Mixtures (MixtureRule): each pair touches at the mean of its diameters and
// exchanges momentum by its masses, so the events follow the reference's only
// if both engines use the same contact distances and masses (and the fast
// one keeps each species with its particle through renumbering, and sizes
// its cells for the largest). Diameters 1 and 1.5 (masses 1 and 1.5^d),
// elastic; diameters 1 and 0.6 with masses 1 and 3, inelastic. phi = 0.25
// keeps free flights well below L/2, as the reference's minimum-image
// predictions need (at N = 150 and phi = 0.15 a small sphere's flight of
// 2.6 time units crossed half the box, and the reference missed its
// collision).
template <int D>
struct Mixture : RuleCase<MixtureRule<ElasticRule>, D> {
  static Scene scene() {
    return test::binary_mixture(test::in_dimension(test::elastic_scene(300, 0.25, 12), D), 0.6, 1.5);
  }
  static MixtureRule<ElasticRule> rule() { return mixture_rule(scene(), ElasticRule{}); }
  static constexpr int kEvents = 600;
};
template <int D>
struct InelasticMixture : RuleCase<MixtureRule<ConstantRestitutionRule>, D> {
  static Scene scene() {
    return test::binary_mixture(test::in_dimension(test::inelastic_scene(300, 0.25, 0.7, 1e-3, 13), D), 0.5, 0.6,
                                3.0);
  }
  static MixtureRule<ConstantRestitutionRule> rule() {
    return mixture_rule(scene(), ConstantRestitutionRule{0.7, 1e-3});
  }
  static constexpr int kEvents = 600;
};

// Viscoelastic: each pair of species has its own b (viscoelastic_pair_b),
// so the events follow only if both engines take the pair's.
template <int D>
struct ViscoelasticMixture : RuleCase<MixtureRule<ViscoelasticRule>, D> {
  static Scene scene() {
    return test::binary_mixture(test::in_dimension(test::elastic_scene(300, 0.25, 14), D), 0.5, 0.6, 3.0);
  }
  static MixtureRule<ViscoelasticRule> rule() { return mixture_rule(scene(), ViscoelasticRule{0.3, 0.0}); }
  static constexpr int kEvents = 600;
};

// 400 unit spheres at phi = 0.05 until 360 merges: aggregates outgrow the
// cells (the large-aggregate index is used), become four times fewer than
// cells (the grid is rebuilt) and merges chain. In 2D, 400 disks at
// phi = 0.1 do the same on one layer of cells, their areas adding; in 1D,
// 400 rods at phi = 0.1 on one row of cells, their lengths adding (no
// chains: a merged rod spans exactly the two it replaces).
template <int D>
struct AggregationCase {
  using EngineType = AggregationEngine;
  struct NoRule {};
  static Scene scene() {
    Scene s = D == 3 ? test::elastic_scene(400, 0.05, 7)
                     : (D == 2 ? test::disk_scene(400, 0.1, 18) : test::rod_scene(400, 0.1, 19));
    s.equilibrate = 0;
    return s;
  }
  static NoRule rule() { return {}; }
  static constexpr int kEvents = 360;
  static std::unique_ptr<EngineType> engine(const Particles& p, NoRule) {
    return std::make_unique<EngineType>(p, AggregateState::unit_spheres(p.size()), 0.0, EngineCounters{}, Geometry(D));
  }
  static std::vector<CollisionRecord> reference(const Particles& p, NoRule, int n) {
    return reference_merges(p, AggregateState::unit_spheres(p.size()), 0.0, 1e9, n, Geometry(D));
  }
};
// Aggregation from a binary mixture (diameters 1 and 1.5, masses 1 and 2):
// each particle starts as an aggregate of its species.
template <int D>
struct AggregationMixture : AggregationCase<D> {
  using typename AggregationCase<D>::NoRule;
  using EngineType = AggregationEngine;
  static Scene scene() { return test::binary_mixture(AggregationCase<D>::scene(), 0.5, 1.5, 2.0); }
  static AggregateState start(const Particles& p) {
    return AggregateState::of_species(p.species, {1.0, 2.0}, {1.0, 1.5});
  }
  static std::unique_ptr<EngineType> engine(const Particles& p, NoRule) {
    return std::make_unique<EngineType>(p, start(p), 0.0, EngineCounters{}, Geometry(D));
  }
  static std::vector<CollisionRecord> reference(const Particles& p, NoRule, int n) {
    return reference_merges(p, start(p), 0.0, 1e9, n, Geometry(D));
  }
};
using Aggregation = AggregationCase<3>;
using Aggregation2D = AggregationCase<2>;
using Aggregation1D = AggregationCase<1>;

template <class Case>
class EngineVsReference : public ::testing::Test {};
using Cases = ::testing::Types<Elastic<3>, DenseElastic<3>, DiluteElastic<3>, Inelastic<3>, Viscoelastic<3>,
                               Aggregation, Elastic<2>, DenseElastic<2>, DiluteElastic<2>, Inelastic<2>,
                               Viscoelastic<2>, Aggregation2D, Elastic<1>, DenseElastic<1>, DiluteElastic<1>,
                               Inelastic<1>, Viscoelastic<1>, Aggregation1D, Rough<3>, Rough<2>,
                               PerfectlyRough<3>, PerfectlyRough<2>, RoughViscoelastic<3>, RoughViscoelastic<2>,
                               Mixture<3>, Mixture<2>, Mixture<1>,
                               InelasticMixture<3>, InelasticMixture<2>, InelasticMixture<1>,
                               ViscoelasticMixture<3>, ViscoelasticMixture<2>, ViscoelasticMixture<1>,
                               AggregationMixture<3>, AggregationMixture<2>, AggregationMixture<1>>;
TYPED_TEST_SUITE(EngineVsReference, Cases);

TYPED_TEST(EngineVsReference, SameEventSequence) {
  const Particles start = initial_state(TypeParam::scene());
  const int n = TypeParam::kEvents;
  const auto ref = TypeParam::reference(start, TypeParam::rule(), n);
  ASSERT_EQ(int(ref.size()), n);
  auto fast = TypeParam::engine(start, TypeParam::rule());
  std::vector<CollisionRecord> log;
  fast->record_collisions(&log);
  while (int(log.size()) < n) fast->run_until(fast->now() + 0.1, 1 << 30, nullptr);
  for (int k = 0; k < n; ++k) {
    ASSERT_EQ(log[k].i, ref[k].i) << "event " << k;
    ASSERT_EQ(log[k].j, ref[k].j) << "event " << k;
    ASSERT_NEAR(log[k].t, ref[k].t, 1e-9 * (1 + ref[k].t)) << "event " << k;
  }
}

// The aggregation cases really go through chains (not in 1D), grid rebuilds
// and the large-aggregate index.
template <class Case>
void expect_chains_and_rebuilds(bool chains = true) {
  const Particles start = initial_state(Case::scene());
  const auto ref = Case::reference(start, {}, Case::kEvents);
  int chained = 0;
  for (std::size_t k = 1; k < ref.size(); ++k) chained += ref[k].t == ref[k - 1].t;
  if (chains) {
    EXPECT_GT(chained, 0);
  }
  auto fast = Case::engine(start, {});
  const double width = fast->cell_width();
  std::size_t most_large = 0;
  while (fast->counters().collisions < Case::kEvents) {
    fast->run_until(fast->now() + 0.1, 1 << 30, nullptr);
    most_large = std::max(most_large, fast->large_aggregates());
  }
  EXPECT_NE(fast->cell_width(), width);
  EXPECT_GT(most_large, 0u);
}
TEST(EngineVsReferenceAggregation, TheCaseHasChainsAndRebuilds) { expect_chains_and_rebuilds<Aggregation>(); }
TEST(EngineVsReferenceAggregation, The2DCaseHasChainsAndRebuilds) { expect_chains_and_rebuilds<Aggregation2D>(); }
TEST(EngineVsReferenceAggregation, The1DCaseHasRebuilds) { expect_chains_and_rebuilds<Aggregation1D>(false); }

// Aggregates of many sizes, growing from wider than a cell up to the L/2
// limit (past the old L/3 one): a 7³ lattice in a box of side 16, every
// fifth site a mass-8 aggregate (diameter 2, which fits the lattice spacing
// 16/7 beside unit spheres), random velocities; in 2D a 9² lattice (spacing
// 1.78) with every fifth site a disk of mass 4 (diameter 2, areas adding).
// The engine runs until it stops at the limit; every merge up to there is
// the reference's, found through the large-aggregate index at periodic
// images far beyond the neighbouring cells, and, near the end, through
// images of the box itself. In 1D, 40 sites on a ring of 64 (spacing 1.6),
// every fifth a rod of length and mass 2.
template <int D>
void expect_same_merges_up_to_half_the_box() {
  const double L = D == 1 ? 64 : 16;
  const int side = D == 3 ? 7 : (D == 2 ? 9 : 40), sites = D == 3 ? side * side * side : (D == 2 ? side * side : side);
  Particles p;
  p.L = L;
  p.resize(std::size_t(sites));
  AggregateState a = AggregateState::unit_spheres(p.size());
  std::uint64_t s = 2024;
  auto uniform = [&s] { return double((s = s * 6364136223846793005ULL + 1442695040888963407ULL) >> 11) * 0x1.0p-53; };
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto at = [&](std::size_t k) { return (double(k % std::size_t(side)) + 0.5) * L / side; };
    p.r[i] = {at(i), D >= 2 ? at(i / std::size_t(side)) : 0.0, D == 3 ? at(i / std::size_t(side * side)) : 0.0};
    p.v[i] = {uniform() - 0.5, D >= 2 ? uniform() - 0.5 : 0.0, D == 3 ? uniform() - 0.5 : 0.0};
    if (i % 5 == 0) a.mass[i] = D == 3 ? 8 : (D == 2 ? 4 : 2), a.diameter[i] = 2;
  }
  AggregationEngine e(p, a, 0.0, EngineCounters{}, Geometry(D));
  std::vector<CollisionRecord> log;
  e.record_collisions(&log);
  std::size_t most_large = 0;
  double widest_cell_multiple = 0;
  bool stopped = false;
  while (!stopped && e.now() < 1e5) {
    try {
      e.run_until(e.now() + 0.25, 1 << 30, nullptr);
    } catch (const RunStopped& stop) {
      EXPECT_EQ(stop.reason, StopReason::kAggregateTooLarge);
      stopped = true;
    }
    most_large = std::max(most_large, e.large_aggregates());
    if (!stopped) widest_cell_multiple = std::max(widest_cell_multiple, e.largest_diameter() / e.cell_width());
  }
  ASSERT_TRUE(stopped);
  EXPECT_GE(e.largest_diameter(), L / 2);
  EXPECT_GT(most_large, 3u);
  EXPECT_GT(widest_cell_multiple, 1.5);  // partners found beyond the neighbouring cells
  const auto ref = reference_merges(p, a, 0.0, 1e9, std::int64_t(log.size()), Geometry(D));
  ASSERT_EQ(ref.size(), log.size());
  for (std::size_t k = 0; k < log.size(); ++k) {
    ASSERT_EQ(log[k].i, ref[k].i) << "merge " << k;
    ASSERT_EQ(log[k].j, ref[k].j) << "merge " << k;
    ASSERT_NEAR(log[k].t, ref[k].t, 1e-9 * (1 + ref[k].t)) << "merge " << k;
  }
}

TEST(EngineVsReferenceAggregation, SameMergesWithLargeAggregatesUpToHalfTheBox) {
  expect_same_merges_up_to_half_the_box<3>();
}
TEST(EngineVsReferenceAggregation, SameMergesWithLargeDisksUpToHalfTheBox) {
  expect_same_merges_up_to_half_the_box<2>();
}
TEST(EngineVsReferenceAggregation, SameMergesWithLongRodsUpToHalfTheRing) {
  expect_same_merges_up_to_half_the_box<1>();
}

}  // namespace
}  // namespace coolgas
