// The simulator's table of collision models (simulate/run/models.h) against
// the file side's (common/trajectory/collision_models.h) and the scene.
#include "simulate/run/models.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/trajectory/collision_models.h"
#include "simulate/scene/scene.h"

namespace coolgas {
namespace {

// One row per enum value, in order, and the same names on both sides: a
// model added to one table and not the other fails here.
TEST(Models, TheSimulatorAndTheFileNameTheSameModels) {
  const auto& rows = model_rows();
  ASSERT_EQ(rows.size(), collision_models().size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(std::size_t(rows[i].model), i) << rows[i].name();
    EXPECT_NE(find_collision_model(rows[i].name()), nullptr) << rows[i].name() << " has no row in collision_models.cc";
    EXPECT_EQ(find_model_row(rows[i].name()), &rows[i]);
    EXPECT_TRUE(rows[i].make && rows[i].restore && rows[i].eta && rows[i].costs) << rows[i].name();
  }
  EXPECT_EQ(find_model_row("sticky"), nullptr);
}

// The scene offers exactly the table's models, and reads each back.
TEST(Models, TheSceneOffersEveryModelByItsName) {
  const auto& keys = scene_keys();
  const auto key = std::find_if(keys.begin(), keys.end(),
                                [](const SceneKey& k) { return std::string(k.key) == "collision.model"; });
  ASSERT_NE(key, keys.end());
  ASSERT_EQ(key->choices.size(), model_rows().size());
  for (const ModelRow& r : model_rows()) {
    EXPECT_EQ(key->choices[std::size_t(r.model)], r.name());
    Scene s;
    s.model = r.model;
    EXPECT_EQ(s.model_name(), r.name());
  }
}

const SceneKey* scene_key(const std::string& name) {
  for (const SceneKey& k : scene_keys())
    if (k.key == name) return &k;
  return nullptr;
}

// Each model parameter of the file side's table is the scene key
// collision.<name> with the row's range and default, offered to exactly the
// models that list it; a scene that gives it runs a file that records it,
// and it is part of the physics a checkpoint keeps (a resume may not change it).
TEST(Models, EachParameterRowIsASceneKeyAFieldAndPhysics) {
  const auto& models = collision_models();
  for (const ModelParameter* p : model_parameters()) {
    const std::string key = "collision." + std::string(p->name);
    const SceneKey* k = scene_key(key);
    ASSERT_NE(k, nullptr) << key;
    EXPECT_EQ(k->lo, p->lo) << key;
    EXPECT_EQ(k->hi, p->hi) << key;
    EXPECT_EQ(k->need, p->default_value ? KeyNeed::kDefault : KeyNeed::kRequired) << key;
    EXPECT_FALSE(key_changeable_on_resume(key));
    for (std::size_t m = 0; m < models.size(); ++m) {
      const auto& listed = models[m].parameters;
      const bool sets = std::find(listed.begin(), listed.end(), p) != listed.end();
      EXPECT_EQ(std::find(k->models.begin(), k->models.end(), CollisionModel(m)) != k->models.end(), sets)
          << key << " for " << models[m].name;
      if (!sets) continue;
      Scene s;
      s.N = 8, s.L = 4, s.phi = s.geometry().covered_fraction(8, 4), s.t_end = 1;
      s.model = CollisionModel(m);
      for (const ModelParameter* q : listed) s.set_parameter(q->name, q->example);
      EXPECT_NE(physics_toml(s).find(std::string(p->name) + " = "), std::string::npos) << key;
      const Scene back = parse_scene(s.to_toml(), "back", {});
      EXPECT_EQ(back.parameter(p->name), p->example) << key;
    }
  }
  EXPECT_THROW(Scene().parameter("sticky"), std::logic_error);
  EXPECT_THROW(Scene().set_parameter("sticky", 1), std::logic_error);
}

}  // namespace
}  // namespace coolgas
