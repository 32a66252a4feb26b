// The fast engine (cells, calendar, lazy positions) reproduces the collision
// sequence of the slow reference engine (all pairs, priority queue) on small
// systems. Chaos amplifies round-off differences, so only the first few
// collisions per particle are compared.
#include <gtest/gtest.h>

#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "simulate/engine/reference_engine.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

template <class Rule>
void expect_same_sequence(const Scene& scene, const Rule& rule, int collisions) {
  const Particles start = initial_state(scene);
  const auto ref = reference_collisions(start, rule, 0.0, 1e9, collisions);
  ASSERT_EQ(int(ref.size()), collisions);
  Engine<Rule> fast(start, rule, 0.0);
  std::vector<CollisionRecord> log;
  fast.record_collisions(&log);
  while (int(log.size()) < collisions) fast.run_until(fast.now() + 0.1, 1 << 30, nullptr);
  for (int k = 0; k < collisions; ++k) {
    ASSERT_EQ(log[k].i, ref[k].i) << "collision " << k;
    ASSERT_EQ(log[k].j, ref[k].j) << "collision " << k;
    ASSERT_NEAR(log[k].t, ref[k].t, 1e-9 * (1 + ref[k].t)) << "collision " << k;
  }
}

TEST(EngineVsReference, ElasticSequenceMatches) {
  expect_same_sequence(test::elastic_scene(120, 0.15, 3), ElasticRule{}, 300);
}

TEST(EngineVsReference, InelasticSequenceMatches) {
  expect_same_sequence(test::inelastic_scene(120, 0.15, 0.5, 1e-3, 4), ConstantRestitutionRule{0.5, 1e-3}, 300);
}

TEST(EngineVsReference, DenseSequenceMatches) {
  expect_same_sequence(test::elastic_scene(200, 0.35, 5), ElasticRule{}, 400);
}

}  // namespace
}  // namespace coolgas
