// The contract every engine keeps with the runner (engine_base.h), checked
// over every model through make_engine: how run_until is sliced (by time or by
// event budget, with observables and frames read in between) changes
// nothing; the budget is honoured exactly; frames are wrapped into the box;
// momentum is kept; an engine restored from its saved state replays the
// same events. Driven gases (simulate/engine/driving.h), rough particles
// (collision.beta, whose spins a restored engine has too) and mixtures
// ([[species]], whose species a restored engine has too) keep it too.
#include <gtest/gtest.h>

#include <cmath>

#include "common/random.h"
#include "simulate/engine/engine.h"
#include "simulate/run/engine_factory.h"
#include "simulate/run/models.h"
#include "simulate/start/initial_state.h"
#include "tests/support/saved_state.h"
#include "tests/support/scenes.h"

namespace coolgas {
namespace {

// A case: a model in a dimension, driven (simulate/engine/driving.h) or
// cooling, with a parameter's effect that can be off (beta) on or off.
struct ModelIn {
  CollisionModel model;
  int dimension;
  bool driven = false;
  bool effect = false;
  bool mixture = false;  // [[species]]: diameters 1 and 1.5, masses 1 and 1.5^d
};

Scene scene_of(const ModelIn& m) {
  Scene s = m.dimension == 3 ? test::inelastic_scene(1500, 0.2, 0.5, 1e-3, 9)
                             : test::inelastic_disk_scene(1500, 0.2, 0.5, 1e-3, 9);
  s.model = m.model;
  // Each of the model's parameters at its row's typical value
  // (common/trajectory/collision_models.h), one that can be off at that value unless the case has its effect.
  for (const ModelParameter* p : collision_models().at(std::size_t(m.model)).parameters)
    s.set_parameter(p->name, p->off && !m.effect ? *p->off : p->example);
  s.equilibrate = 0;
  if (m.driven) s.driving_power = 0.1;  // a kick every half collision time
  if (m.dimension == 1) s = test::in_dimension(s, 1);
  if (m.mixture) s = test::binary_mixture(s, 0.5, 1.5);
  return s;
}

class EngineContract : public ::testing::TestWithParam<ModelIn> {};

// Aggregates outgrow this small box (half its side) later: stop at t = 8, before.
double end_of(CollisionModel m) { return m == CollisionModel::kAggregation ? 8 : 40; }

TEST_P(EngineContract, SlicingChangesNothingAndFramesAreWrapped) {
  const Scene s = scene_of(GetParam());
  const double kEnd = end_of(GetParam().model);
  const Particles start = initial_state(s);
  auto whole = make_engine(s, start, 0.0);
  ASSERT_EQ(whole->run_until(kEnd, std::int64_t(1) << 40, nullptr), RunStatus::kReached);

  auto sliced = make_engine(s, start, 0.0);
  const Vec3 p0 = sliced->observables().momentum;
  double speeds = 0;
  for (const Vec3& v : sliced->frame().velocity) speeds += std::sqrt(dot(v, v));
  Random rng(5);
  std::unique_ptr<EngineBase> restored;
  while (sliced->now() < kEnd) {
    const double t = std::min(kEnd, sliced->now() + 2 * rng.uniform());
    const std::int64_t budget = 1 + std::int64_t(rng.below(3000));
    const std::int64_t events = sliced->counters().events;
    const RunStatus status = sliced->run_until(t, budget, nullptr);
    if (status == RunStatus::kEventBudget) EXPECT_EQ(sliced->counters().events - events, budget);
    else EXPECT_LE(sliced->counters().events - events, budget);
    const EngineFrame f = sliced->frame();
    for (const Vec3& r : f.position)
      for (int d = 0; d < 3; ++d) ASSERT_TRUE(r[d] >= 0 && r[d] < s.L) << r[d];
    const Vec3 p = sliced->observables().momentum;
    for (int d = 0; d < 3; ++d) ASSERT_NEAR(p[d], p0[d], 1e-12 * speeds);
    if (!restored && sliced->now() > kEnd / 2) restored = restore_engine(s, test::saved_state(*sliced));
  }
  ASSERT_TRUE(restored);
  ASSERT_EQ(restored->run_until(kEnd, std::int64_t(1) << 40, nullptr), RunStatus::kReached);
  EXPECT_GT(whole->counters().collisions, 500);
  EXPECT_EQ(sliced->counters().events, whole->counters().events);
  EXPECT_EQ(restored->counters().events, whole->counters().events);
  test::expect_same_frame(sliced->frame(), whole->frame());
  test::expect_same_frame(restored->frame(), whole->frame());
  const Observables a = sliced->observables(), b = whole->observables();
  EXPECT_EQ(a.kinetic_energy, b.kinetic_energy);
  EXPECT_EQ(a.rotational_energy, b.rotational_energy);
  EXPECT_EQ(a.rotational_energy.has_value(), s.rough());
  EXPECT_EQ(a.aggregates.has_value(), GetParam().model == CollisionModel::kAggregation);
  EXPECT_EQ(a.species_energy, b.species_energy);
  EXPECT_EQ(a.species_energy.size(), s.species.size());
}

// Long enough for the engine's own rebuilds (every 200 collisions per
// particle): they fall on the same events however the run is sliced, and a
// restored engine keeps their schedule.
TEST(EngineContractRebuilds, ScheduledRebuildsDoNotDependOnSlicing) {
  const Scene s = test::elastic_scene(300, 0.2, 12);
  const Particles start = initial_state(s);
  const std::int64_t target = 300 * 700 / 2;  // 700 collisions per particle: three rebuilds
  Engine<ElasticRule> whole(start, ElasticRule{}, 0.0), sliced(start, ElasticRule{}, 0.0);
  while (whole.counters().collisions < target) whole.run_until(whole.now() + 50, std::int64_t(1) << 40, nullptr);
  std::unique_ptr<Engine<ElasticRule>> restored;
  Random rng(3);
  while (sliced.now() < whole.now()) {
    sliced.run_until(std::min(whole.now(), sliced.now() + rng.uniform()), 1 + std::int64_t(rng.below(5000)), nullptr);
    if (!restored && sliced.counters().collisions > target / 2)
      restored = std::make_unique<Engine<ElasticRule>>(ElasticRule{}, test::saved_state(sliced));
  }
  ASSERT_TRUE(restored);
  restored->run_until(whole.now(), std::int64_t(1) << 40, nullptr);
  EXPECT_EQ(sliced.counters().events, whole.counters().events);
  test::expect_same_frame(sliced.frame(), whole.frame());
  test::expect_same_frame(restored->frame(), whole.frame());
}

// Whether a model has a parameter whose effect can be off (beta: rough particles).
bool has_effect(CollisionModel m) {
  for (const ModelParameter* p : collision_models().at(std::size_t(m)).parameters)
    if (p->off) return true;
  return false;
}

// Every model of the simulator's table (simulate/run/models.h), so a new
// model is held to the contract from its first row, in 3D and in 2D, and
// with its effect (rough particles) on, cooling and driven.
std::vector<ModelIn> every_model() {
  std::vector<ModelIn> models;
  for (const int dimension : {3, 2})
    for (const ModelRow& r : model_rows())
      for (const bool effect : {false, true}) {
        if (effect && !has_effect(r.model)) continue;
        models.push_back({r.model, dimension, false, effect});
        if (r.model != CollisionModel::kAggregation) models.push_back({r.model, dimension, true, effect});
      }
  // Mixtures of the models that offer them, in every dimension.
  for (const int dimension : {3, 2, 1})
    for (const CollisionModel m : {CollisionModel::kElastic, CollisionModel::kInelastic})
      models.push_back({m, dimension, false, false, true});
  return models;
}
std::string case_name(const ::testing::TestParamInfo<ModelIn>& info) {
  return model_name(info.param.model) + "_" + std::to_string(info.param.dimension) + "D" +
         (info.param.driven ? "_driven" : "") + (info.param.effect ? "_rough" : "") +
         (info.param.mixture ? "_mixture" : "");
}
INSTANTIATE_TEST_SUITE_P(EveryModel, EngineContract, ::testing::ValuesIn(every_model()), case_name);

}  // namespace
}  // namespace coolgas
