// The scene: what to simulate, read from TOML (toml11) with command-line
// `--set key=value` overrides. Every key is one row of scene_keys(), which
// parses, checks, prints the scene part of `coolgas-simulate --help` and
// writes the effective scene back as TOML.
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "common/geometry.h"
#include "common/limits.h"
#include "common/trajectory/collision_models.h"
#include "common/trajectory/run_parameters.h"

namespace coolgas {

// kFile: a frame of a file (simulate/start/file_start.h).
enum class InitialPositions { kRandom, kFcc, kFile };
// kViscoelastic: velocity-dependent restitution (simulate/engine/collision_rules.h);
// kAggregation: ballistic aggregation, spheres that touch merge (simulate/engine/aggregation_engine.h).
// The order is that of the file side's table, common/trajectory/collision_models.h,
// which names each model (tests/unit/simulate/run/models_test.cc).
enum class CollisionModel { kElastic, kInelastic, kViscoelastic, kAggregation };
// driving.period when the scene does not give it: a kick every half mean
// collision time (docs/simulate.md, "Driven gas": cost and accuracy).
inline constexpr double kDefaultKickPeriod = 0.5;
// collision.model and /parameters/model of `m`: "elastic", ...
std::string model_name(CollisionModel m);

// One species of a mixture, a [[species]] table of the scene: its share of
// the number of particles, its diameter and its mass (absent: diameter^d,
// the unit particle's density). Lengths and masses are in the units the
// scene writes them in, those of the equal-particle gas (its particles have
// diameter 1 and mass 1); docs/simulate.md, "Mixtures".
struct Species {
  double fraction = 0;
  double diameter = 1;
  std::optional<double> mass;
};
// The most species a scene may list: those a file holds.
inline constexpr int kMaxSpecies = int(kMaxFileSpecies);

struct Scene {
  // system
  int dimension = 3;  // 3: spheres in a periodic cube; 2: disks in a periodic square; 1: rods on a ring
  std::int64_t N = 0;
  double L = 0;    // box side, diameters
  double phi = 0;  // volume fraction N π / (6 L³) (2D: area fraction N π / (4 L²); 1D: N / L; common/geometry.h)
  std::int64_t seed = 1;
  InitialPositions init = InitialPositions::kRandom;
  // Elastic dynamics run before t = 0 to turn the packing into an equilibrium
  // fluid (random sequential addition is not one: its contact value differs
  // from Carnahan–Starling, so the collision rate would start 5-20 % off).
  double equilibrate = 5.0;
  // init = "file": the file, the time of its frame (none: the last frame),
  // and the temperature that sets the time unit (0 until the file is read:
  // its own T0 for a coolgas file, else the Enskog value below).
  std::string from;
  std::optional<double> from_time;
  double T0 = 0;
  // system.inertia: rough particles' moment of inertia per m a² (a the
  // radius); absent: a uniform ball's (Geometry::uniform_inertia).
  std::optional<double> inertia;
  // [[species]]: a mixture of sizes and masses; empty: equal unit particles.
  std::vector<Species> species;
  // collision
  CollisionModel model = CollisionModel::kElastic;
  // The model's parameters collision.<name> (common/trajectory/collision_models.h)
  // the scene gives; the others take their defaults.
  ParameterValues collision;
  // driving (simulate/engine/driving.h): the power of the white-noise
  // kicks (none: a freely cooling gas) and their interval.
  std::optional<double> driving_power;
  double driving_period = kDefaultKickPeriod;
  // run
  double t_end = 0;
  // output
  int observables_per_decade = 20;
  int dumps_per_decade = 5;
  double t_min = 0.01;
  std::vector<double> dump_times;

  // Not part of the scene: when a --set of N, L or phi changed the one of
  // the three the scene gave but the override did not keep, what changed
  // ("system.L = 91.07, not the scene's 48: ..."), for the user to see;
  // else empty.
  std::string size_note;

  // The complete effective scene as TOML; parse_scene() of it gives this scene back.
  std::string to_toml() const;
  std::string model_name() const;
  Geometry geometry() const { return Geometry(dimension); }
  // collision.beta > -1: the particles spin and collisions turn them.
  bool rough() const { return is_rough(collision); }
  // [[species]] given: particles of several sizes and masses.
  bool mixture() const { return !species.empty(); }
  // Species k's mass: its `mass`, else diameter^d.
  double species_mass(std::size_t k) const;
  // The particles of each species: fraction x N rounded so that they add up
  // to N (largest remainders; ties to the earlier species). Particle ids
  // follow the table: species 0 first.
  std::vector<std::int64_t> species_counts() const;
  // The diameter of the largest particle (1 without [[species]]): cells are that wide.
  double largest_diameter() const;
  // The particles' total measure in unit particles: sum over species of
  // N_k diameter_k^d (N without [[species]]); phi = covered_fraction of it.
  double unit_particles() const;
  // system.inertia, else a uniform ball's in the scene's dimension.
  double particle_inertia() const { return inertia.value_or(geometry().uniform_inertia()); }
  // collision.<name>: the scene's value, else the parameter's default;
  // std::logic_error for a name no model has, or one without a default not given.
  double parameter(std::string_view name) const;
  // std::logic_error for a name no model has; the range is parse_scene()'s to check.
  void set_parameter(std::string_view name, double value);
};

// One row per scene key: it parses, checks, prints --help and writes TOML.
enum class KeyType { kInteger, kFloat, kString, kFloatArray };
// A key's value converted to its type (integers given as exact floats, 1e4, count).
using SceneValue = std::variant<std::int64_t, double, std::string, std::vector<double>>;
// kDefault: the key has a default (Scene{}'s member); kRequired: no default;
// kSize: system.N, system.L, system.phi, of which a scene gives two;
// kOptional: no default, its absence has a meaning (the help says which).
enum class KeyNeed { kDefault, kRequired, kSize, kOptional };

// Rows are written with designated initializers; a field a row leaves out
// takes the default here.
struct SceneKey {
  std::string key;  // "table.name"
  KeyType type = KeyType::kFloat;
  KeyNeed need = KeyNeed::kDefault;
  std::string help;  // meaning and units; --help adds the range and the default
  // Numbers (each element of an array): lo <= x <= hi, strict where *_open;
  // infinite bounds mean none, and every number must be finite.
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  std::vector<std::string> choices = {};  // strings: the allowed values
  // Models that use the key (collision.* keys; empty: every model).
  std::vector<CollisionModel> models = {};
  // Starts that use the key (system.init; empty: every start).
  std::vector<InitialPositions> inits = {};
  std::function<void(Scene&, const SceneValue&)> set;
  // The member as a TOML value ("" for an absent kOptional key, or a
  // parameter without a default the scene does not give).
  std::function<std::string(const Scene&)> toml;
};
const std::vector<SceneKey>& scene_keys();

// The scene part of `coolgas-simulate --help`: one line per key with its
// type, range and default.
std::string scene_keys_help();

// The highest volume fraction offered for random sequential addition (its
// saturation limit is 0.3841; Torquato et al. 2006). The voxel phase
// (simulate/start/rsa_voxels.h) reaches it, but the cost per sphere grows towards
// saturation: placing N = 10^6 takes about 5 s at phi = 0.35, 6.5 s at 0.36
// and 9 s at 0.37 on one core (tests/bench/rsa_bench.cc), against more than
// 12 minutes (unfinished) for plain RSA. 0.36 leaves a margin for larger N.
inline constexpr double kMaxRandomPhi = 0.36;
// The same for disks (saturation at 0.547; Feder 1980), placed by plain
// trials (simulate/start/rsa_disks.h), whose cost grows steeply towards it.
inline constexpr double kMaxRandomPhi2D = 0.45;
// The same for a mixture, placed by plain trials, largest first
// (simulate/start/rsa_mixture.h), in 3D and 2D; rods of any lengths are
// placed exactly at any density below 1.
inline constexpr double kMaxMixturePhi = 0.30;
inline constexpr double kMaxMixturePhi2D = 0.40;
// FCC lattice with nearest neighbours at one diameter: π/(3√2).
inline constexpr double kMaxFccPhi = 0.7404;

// Parses and checks a scene. `overrides` are "key=value" strings (values in
// TOML syntax; a bare word is taken as a string). An override of one of
// system.N, L, phi replaces the scene's own: of the scene's two, phi is kept
// before N before L, and the third follows. Throws InputError with one line:
// unknown keys (with a did-you-mean), wrong types, out-of-range values, a
// text too large or too deeply nested for the TOML parser, and values whose
// cost is absurd (memory, collisions, rows and dumps; see check_scene_cost).
Scene parse_scene(const std::string& toml_text, const std::string& source, const std::vector<std::string>& overrides);

// The most the scene may cost (check_scene_cost); the memory available
// (common/memory.h) is read at run time.
inline constexpr double kBytesPerParticle = 180;  // engine, measured (tests/bench/README.md)
inline constexpr double kBytesPerCell = 20;       // the gas engine's grid of L^3 cells, measured
inline constexpr double kMaxCells = kMaxIndex32;      // cell indices are 32-bit
inline constexpr double kMaxParticles = kMaxIndex32;  // particle ids are 32-bit
inline constexpr double kMaxEquilibrationCollisions = 1e12;  // about 3 weeks at 5e5 collisions/s
inline constexpr double kMaxObservableRows = 1e5;
inline constexpr double kMaxDumps = 1e4;
// Scene texts above this size, or nested deeper, are refused before parsing.
inline constexpr std::size_t kMaxSceneBytes = 1 << 20;
inline constexpr int kMaxSceneNesting = 16;

// Refuses (InputError, one line saying what the scene would cost and the
// limit) a scene whose memory exceeds `memory_bytes` or the limits above.
void check_scene_cost(const Scene& scene, double memory_bytes);

// The checks that need the box: it fits the cell grid, and the cost against
// the memory available. parse_scene() makes them; a start from a file,
// whose size is known only once the file is read, makes them then.
void check_scene_size(const Scene& scene);

// "" if s.phi is below close packing in s's dimension (every start, generated
// or from a file, must be: at it nothing moves), else why not, for a message.
std::string check_close_packing(const Scene& s);

// Keys a resumed run may change (run.* and output.*); others are rejected.
bool key_changeable_on_resume(const std::string& key);

// The scene's physics as TOML: every key a resume may not change, as the
// scene has it (the others at their defaults). A checkpoint belongs to the
// run whose physics it records.
std::string physics_toml(const Scene& s);

}  // namespace coolgas
