// Every engine against a slow, plainly correct reference, in one typed test
// body: the three rules of Engine<Rule, D> in 3D and 2D (cells, calendar,
// lazy positions) against the all-pairs reference engine, and the aggregation engine (chains,
// a grid that is rebuilt as aggregates grow) against the all-pairs
// aggregation reference. Chaos amplifies round-off differences, so only the
// first few events per particle are compared.
#include <gtest/gtest.h>

#include <memory>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/engine/engine.h"
#include "simulate/engine/reference_engine.h"
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

struct Elastic : RuleCase<ElasticRule> {
  static Scene scene() { return test::elastic_scene(120, 0.15, 3); }
  static ElasticRule rule() { return {}; }
  static constexpr int kEvents = 300;
};
struct DenseElastic : RuleCase<ElasticRule> {
  static Scene scene() { return test::elastic_scene(200, 0.35, 5); }
  static ElasticRule rule() { return {}; }
  static constexpr int kEvents = 400;
};
// phi = 0.02: one-diameter cells would be 24 per particle, so the engine's
// cells are one mean spacing wide (cell_width, engine.cc: 10 per side of
// L = 29.7, 2.97 wide). The box is large enough that free flights (mean
// 5.9) stay well below L/2, as the reference's minimum-image predictions
// need.
struct DiluteElastic : RuleCase<ElasticRule> {
  static Scene scene() { return test::elastic_scene(1000, 0.02, 8); }
  static ElasticRule rule() { return {}; }
  static constexpr int kEvents = 600;
};
struct Inelastic : RuleCase<ConstantRestitutionRule> {
  static Scene scene() { return test::inelastic_scene(120, 0.15, 0.5, 1e-3, 4); }
  static ConstantRestitutionRule rule() { return {0.5, 1e-3}; }
  static constexpr int kEvents = 300;
};
struct Viscoelastic : RuleCase<ViscoelasticRule> {
  static Scene scene() { return test::elastic_scene(120, 0.15, 6); }
  static ViscoelasticRule rule() { return {0.3, 0.0}; }
  static constexpr int kEvents = 300;
};
// The same rules for disks (D = 2): one layer of cells, 9 around each. The
// reference needs no second version: it works on 3-vectors whose z stays 0.
struct Elastic2D : RuleCase<ElasticRule, 2> {
  static Scene scene() { return test::disk_scene(150, 0.2, 13); }
  static ElasticRule rule() { return {}; }
  static constexpr int kEvents = 300;
};
struct DenseElastic2D : RuleCase<ElasticRule, 2> {
  static Scene scene() { return test::disk_scene(250, 0.45, 14); }
  static ElasticRule rule() { return {}; }
  static constexpr int kEvents = 400;
};
// phi = 0.01: cells one mean spacing wide (cell_width, engine.cc: 3.5 wide
// in a square of side 126), free flights (mean 39) below L/2.
struct DiluteElastic2D : RuleCase<ElasticRule, 2> {
  static Scene scene() { return test::disk_scene(2000, 0.01, 15); }
  static ElasticRule rule() { return {}; }
  static constexpr int kEvents = 600;
};
struct Inelastic2D : RuleCase<ConstantRestitutionRule, 2> {
  static Scene scene() { return test::inelastic_disk_scene(150, 0.2, 0.5, 1e-3, 16); }
  static ConstantRestitutionRule rule() { return {0.5, 1e-3}; }
  static constexpr int kEvents = 300;
};
struct Viscoelastic2D : RuleCase<ViscoelasticRule, 2> {
  static Scene scene() { return test::disk_scene(150, 0.2, 17); }
  static ViscoelasticRule rule() { return {0.3, 0.0}; }
  static constexpr int kEvents = 300;
};

// 400 unit spheres at phi = 0.05 until 360 merges: aggregates outgrow the
// cells (the large-aggregate index is used), become four times fewer than
// cells (the grid is rebuilt) and merges chain.
struct Aggregation {
  using EngineType = AggregationEngine;
  struct NoRule {};
  static Scene scene() {
    Scene s = test::elastic_scene(400, 0.05, 7);
    s.equilibrate = 0;
    return s;
  }
  static NoRule rule() { return {}; }
  static constexpr int kEvents = 360;
  static std::unique_ptr<EngineType> engine(const Particles& p, NoRule) {
    return std::make_unique<EngineType>(p, AggregateState::unit_spheres(p.size()), 0.0);
  }
  static std::vector<CollisionRecord> reference(const Particles& p, NoRule, int n) {
    return reference_merges(p, AggregateState::unit_spheres(p.size()), 0.0, 1e9, n);
  }
};

template <class Case>
class EngineVsReference : public ::testing::Test {};
using Cases = ::testing::Types<Elastic, DenseElastic, DiluteElastic, Inelastic, Viscoelastic, Aggregation, Elastic2D,
                               DenseElastic2D, DiluteElastic2D, Inelastic2D, Viscoelastic2D>;
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

// The aggregation case really goes through chains, grid rebuilds and the large-aggregate index.
TEST(EngineVsReferenceAggregation, TheCaseHasChainsAndRebuilds) {
  const Particles start = initial_state(Aggregation::scene());
  const auto ref = Aggregation::reference(start, {}, Aggregation::kEvents);
  int chained = 0;
  for (std::size_t k = 1; k < ref.size(); ++k) chained += ref[k].t == ref[k - 1].t;
  EXPECT_GT(chained, 0);
  auto fast = Aggregation::engine(start, {});
  const double width = fast->cell_width();
  std::size_t most_large = 0;
  while (fast->counters().collisions < Aggregation::kEvents) {
    fast->run_until(fast->now() + 0.1, 1 << 30, nullptr);
    most_large = std::max(most_large, fast->large_aggregates());
  }
  EXPECT_NE(fast->cell_width(), width);
  EXPECT_GT(most_large, 0u);
}

// Aggregates of many sizes, growing from wider than a cell up to the L/2
// limit (past the old L/3 one): a 7³ lattice in a box of side 16, every
// fifth site a mass-8 aggregate (diameter 2, which fits the lattice spacing
// 16/7 beside unit spheres), random velocities. The engine runs until it
// stops at the limit; every merge up to there is the reference's, found
// through the large-aggregate index at periodic images far beyond the 27
// neighbours, and, near the end, through images of the box itself.
TEST(EngineVsReferenceAggregation, SameMergesWithLargeAggregatesUpToHalfTheBox) {
  const double L = 16;
  Particles p;
  p.L = L;
  p.resize(343);
  AggregateState a = AggregateState::unit_spheres(p.size());
  std::uint64_t s = 2024;
  auto uniform = [&s] { return double((s = s * 6364136223846793005ULL + 1442695040888963407ULL) >> 11) * 0x1.0p-53; };
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.r[i] = {(double(i % 7) + 0.5) * L / 7, (double(i / 7 % 7) + 0.5) * L / 7, (double(i / 49) + 0.5) * L / 7};
    p.v[i] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
    if (i % 5 == 0) a.mass[i] = 8, a.diameter[i] = 2;
  }
  AggregationEngine e(p, a, 0.0);
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
  EXPECT_GT(widest_cell_multiple, 1.5);  // partners found beyond the 27 neighbouring cells
  const auto ref = reference_merges(p, a, 0.0, 1e9, std::int64_t(log.size()));
  ASSERT_EQ(ref.size(), log.size());
  for (std::size_t k = 0; k < log.size(); ++k) {
    ASSERT_EQ(log[k].i, ref[k].i) << "merge " << k;
    ASSERT_EQ(log[k].j, ref[k].j) << "merge " << k;
    ASSERT_NEAR(log[k].t, ref[k].t, 1e-9 * (1 + ref[k].t)) << "merge " << k;
  }
}

}  // namespace
}  // namespace coolgas
