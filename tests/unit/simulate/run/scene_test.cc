// Scenes: sizes derived consistently, the effective scene reads back to the
// same scene, and bad values are refused with a message naming them.
#include "simulate/run/scene.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"

namespace coolgas {
namespace {

const char* kScene = R"(
[system]
N = 1000
phi = 0.208
[collision]
model = "inelastic"
r0 = 0.1
delta = 1e-4
[run]
t_end = 100
)";

std::string error_of(const std::vector<std::string>& overrides, const std::string& text = kScene) {
  try {
    parse_scene(text, "s.toml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, BoxSideFollowsFromNAndPhi) {
  const Scene s = parse_scene(kScene, "s.toml", {});
  EXPECT_NEAR(double(s.N) * M_PI / (6 * s.L * s.L * s.L), 0.208, 1e-15);
  EXPECT_EQ(s.r0, 0.1);
  const Scene t = parse_scene(kScene, "s.toml", {"system.N=8000"});
  EXPECT_NEAR(t.L, 2 * s.L, 1e-12);  // 8x the particles at the same phi: twice the side
}

TEST(Scene, EffectiveSceneReadsBackIdentically) {
  const Scene s = parse_scene(kScene, "s.toml", {"output.dump_times=[5, 10.5]", "system.seed=99"});
  const Scene t = parse_scene(s.to_toml(), "effective", {});
  EXPECT_EQ(t.to_toml(), s.to_toml());
  EXPECT_EQ(t.L, s.L);
  EXPECT_EQ(t.dump_times, (std::vector<double>{5, 10.5}));
  EXPECT_EQ(t.seed, 99);
}

TEST(Scene, UnknownKeyGetsADidYouMean) {
  EXPECT_NE(error_of({"system.phy=0.1"}).find("did you mean 'system.phi'"), std::string::npos);
  EXPECT_NE(error_of({"colision.r0=0.5"}).find("did you mean 'collision.r0'"), std::string::npos);
}

TEST(Scene, OutOfRangeValuesAreNamed) {
  EXPECT_NE(error_of({"system.phi=0"}).find("system.phi"), std::string::npos);
  EXPECT_NE(error_of({"system.phi=0.4"}).find("fcc"), std::string::npos);  // beyond RSA: suggests the lattice
  EXPECT_NE(error_of({"system.N=1"}).find("system.N"), std::string::npos);
  EXPECT_NE(error_of({"collision.r0=0"}).find("collision.r0"), std::string::npos);
  EXPECT_NE(error_of({"collision.r0=1.5"}).find("collision.r0"), std::string::npos);
  EXPECT_NE(error_of({"collision.delta=-1"}).find("collision.delta"), std::string::npos);
  EXPECT_NE(error_of({"run.t_end=0"}).find("run.t_end"), std::string::npos);
  EXPECT_NE(error_of({"system.N=3"}).find("too small"), std::string::npos);  // box below 3 cells
  EXPECT_NE(error_of({"system.N=1.5"}).find("integer"), std::string::npos);
  EXPECT_NE(error_of({"collision.model=sticky"}).find("collision.model"), std::string::npos);
  EXPECT_NE(error_of({}, "[system]\nN = 10\n[run]\nt_end = 1\n").find("two of"), std::string::npos);
  EXPECT_NE(error_of({}, "[system\n").find("not valid TOML"), std::string::npos);
}

TEST(Scene, AllowsFccUpToItsClosePacking) {
  EXPECT_EQ(error_of({"system.phi=0.45", "system.init=fcc"}), "");
  EXPECT_NE(error_of({"system.phi=0.75", "system.init=fcc"}).find("0.7404"), std::string::npos);
}

}  // namespace
}  // namespace coolgas
