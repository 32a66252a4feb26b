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

}  // namespace
}  // namespace coolgas
