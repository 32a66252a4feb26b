// Scenes of the effects models: the effective scene written into a file
// (to_toml) parses back to the same scene, and each model takes only its own
// collision keys.
#include <gtest/gtest.h>

#include "common/error.h"
#include "simulate/scene/scene.h"

namespace coolgas {
namespace {

const char* kBase = "[system]\nN = 2000\nphi = 0.2\n[run]\nt_end = 10\n";

TEST(EffectsScene, ViscoelasticRoundTripsThroughToToml) {
  const Scene s = parse_scene(kBase, "test", {"collision.model=viscoelastic", "collision.viscoelastic_b=0.125",
                                              "collision.delta=1e-5"});
  EXPECT_EQ(s.model, CollisionModel::kViscoelastic);
  EXPECT_EQ(s.model_name(), "viscoelastic");
  EXPECT_EQ(s.parameter("viscoelastic_b"), 0.125);
  EXPECT_EQ(s.parameter("r0"), 1.0);  // unused by this model
  const Scene back = parse_scene(s.to_toml(), "round trip", {});
  EXPECT_EQ(back.model, s.model);
  EXPECT_EQ(back.parameter("viscoelastic_b"), s.parameter("viscoelastic_b"));
  EXPECT_EQ(back.parameter("delta"), s.parameter("delta"));
  EXPECT_EQ(back.to_toml(), s.to_toml());
}

TEST(EffectsScene, AggregationRoundTripsAndTakesNoRestitutionKeys) {
  const Scene s = parse_scene(kBase, "test", {"collision.model=aggregation"});
  EXPECT_EQ(s.model_name(), "aggregation");
  EXPECT_EQ(parse_scene(s.to_toml(), "round trip", {}).to_toml(), s.to_toml());
  for (const char* key : {"collision.r0=0.5", "collision.delta=1e-4", "collision.viscoelastic_b=0.1"})
    EXPECT_THROW(parse_scene(kBase, "test", {"collision.model=aggregation", key}), InputError) << key;
}

TEST(EffectsScene, ViscoelasticNeedsAPositiveConstant) {
  for (const char* b : {"collision.viscoelastic_b=0", "collision.viscoelastic_b=-1", "collision.viscoelastic_b=inf"})
    EXPECT_THROW(parse_scene(kBase, "test", {"collision.model=viscoelastic", b}), InputError) << b;
  EXPECT_THROW(parse_scene(kBase, "test", {"collision.model=viscoelastic"}), InputError);
  EXPECT_THROW(parse_scene(kBase, "test", {"collision.viscoelastic_b=0.1"}), InputError);  // elastic by default
}

}  // namespace
}  // namespace coolgas
