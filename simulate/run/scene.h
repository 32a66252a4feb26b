// The scene: what to simulate, read from TOML (toml11) with command-line
// `--set key=value` overrides. Every key is listed once in scene_keys(),
// which also produces the scene part of `coolgas-simulate --help`.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace coolgas {

enum class InitialPositions { kRandom, kFcc };
// kViscoelastic: velocity-dependent restitution (simulate/engine/collision_rules.h);
// kAggregation: ballistic aggregation, spheres that touch merge (simulate/engine/aggregation_engine.h).
enum class CollisionModel { kElastic, kInelastic, kViscoelastic, kAggregation };

struct Scene {
  // system
  std::int64_t N = 0;
  double L = 0;    // box side, diameters
  double phi = 0;  // volume fraction N π / (6 L³)
  std::int64_t seed = 1;
  InitialPositions init = InitialPositions::kRandom;
  // Elastic dynamics run before t = 0 to turn the packing into an equilibrium
  // fluid (random sequential addition is not one: its contact value differs
  // from Carnahan–Starling, so the collision rate would start 5-20 % off).
  double equilibrate = 5.0;
  // collision
  CollisionModel model = CollisionModel::kElastic;
  double r0 = 1.0;
  double delta = 0.0;
  double viscoelastic_b = 0.0;  // b = A alpha^{2/5} of the viscoelastic model, (sigma omega0)^{-1/5}
  // run
  double t_end = 0;
  // output
  int observables_per_decade = 20;
  int dumps_per_decade = 5;
  double t_min = 0.01;
  std::vector<double> dump_times;

  // The complete effective scene as TOML; parse_scene() of it gives this scene back.
  std::string to_toml() const;
  std::string model_name() const;
};

struct SceneKey {
  const char* key;
  const char* type;  // "integer", "float", "string", "array of floats"
  const char* help;  // meaning, units and default
};
const std::vector<SceneKey>& scene_keys();

// The highest volume fraction offered for random sequential addition (its
// saturation limit is 0.3841; Torquato et al. 2006). The voxel phase
// (simulate/start/rsa_voxels.h) reaches it, but the cost per sphere grows towards
// saturation: placing N = 10^6 takes about 5 s at phi = 0.35, 6.5 s at 0.36
// and 9 s at 0.37 on one core (tests/bench/rsa_bench.cc), against more than
// 12 minutes (unfinished) for plain RSA. 0.36 leaves a margin for larger N.
inline constexpr double kMaxRandomPhi = 0.36;
// FCC lattice with nearest neighbours at one diameter: π/(3√2).
inline constexpr double kMaxFccPhi = 0.7404;

// Parses and checks a scene. `overrides` are "key=value" strings (values in
// TOML syntax; a bare word is taken as a string). Throws InputError with one
// line: unknown keys (with a did-you-mean), wrong types, out-of-range values.
Scene parse_scene(const std::string& toml_text, const std::string& source, const std::vector<std::string>& overrides);

// Keys a resumed run may change (run.* and output.*); others are rejected.
bool key_changeable_on_resume(const std::string& key);

}  // namespace coolgas
