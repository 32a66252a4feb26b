// The run's parameters as one table: every /parameters attribute of a
// trajectory, with its type, meaning and role. The writer, the readers (run
// info, resume), the ensemble check, the provenance of the tools' tables and
// the validator's profile all walk run_parameter_fields(). A new common
// parameter is a member here and a row in run_parameters.cc; a new model
// parameter is only a row of collision_models.cc.
#pragma once
#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "common/limits.h"
#include "common/trajectory/collision_models.h"
#include "common/tsv.h"

namespace coolgas {

struct RunParameters {
  std::int64_t schema_version = 0;  // set by the writer from the model table
  std::string program_version;      // set by the writer: the coolgas-simulate that wrote the file
  std::string scene_toml;           // the complete effective scene
  std::int64_t seed = 0;
  std::int64_t N = 0;
  double L = 0, phi = 0, T0 = 0;
  std::string model = "elastic";
  // Model-specific (collision_models.h), by name: present exactly when the
  // model uses them. The defaults are those of the default model, elastic spheres.
  ParameterValues collision = {{"r0", 1.0}, {"delta", 0.0}};
  // The driven gas (simulate/engine/driving.h): present exactly when the run
  // is driven (the scene's [driving]); files of a driven run are of schema
  // version kDrivingSchemaVersion or later.
  std::optional<double> driving_power, driving_period;
  // Rough particles' moment of inertia per m a² (a the radius): present
  // exactly when the run is rough (collision beta > -1, is_rough()).
  std::optional<double> inertia;
  // A mixture's species table (the scene's [[species]], one value per
  // species, in the table's order): present exactly when the run is a
  // mixture, whose files are of schema version kMixtureSchemaVersion or later.
  std::vector<double> species_fraction, species_diameter, species_mass;
};

inline constexpr std::int64_t kDrivingSchemaVersion = 4;
// Mixtures: the species table above, each particle's species in the dumps
// and each species' kinetic energy among the observables.
inline constexpr std::int64_t kMixtureSchemaVersion = 6;
// The most species a file may list (the simulator's limit, scene.h).
inline constexpr std::size_t kMaxFileSpecies = 16;
// Whether a run's parameters are a mixture's (species_fraction given).
inline bool is_mixture(const RunParameters& p) { return !p.species_fraction.empty(); }
// Whether the run's files hold each particle's species and each species'
// kinetic energy: a mixture's, but for aggregation's (model_keeps_species).
bool has_particle_species(const RunParameters& p);

// kPhysics: defines "the same physics"; runs of one ensemble agree in it.
// kSeed: what the runs of an ensemble differ in.
// kRecord: how the file was made (scene text, versions); not compared.
enum class ParameterRole { kPhysics, kSeed, kRecord };

// The member of a model-specific field: RunParameters::collision[name].
struct ModelValue {};

struct ParameterField {
  using Member = std::variant<std::int64_t RunParameters::*, double RunParameters::*, std::string RunParameters::*,
                              std::optional<double> RunParameters::*, ModelValue,
                              std::vector<double> RunParameters::*>;
  std::string_view name;  // the /parameters attribute
  Member member;          // ModelValue: model-specific, one field per row of model_parameters();
                          // std::optional: present in some runs of every model (driving);
                          // std::vector: one value per species, present in mixtures only
  std::string_view meaning;
  ParameterRole role = ParameterRole::kPhysics;
  int since = 1;                         // schema version that added it
  std::optional<std::int64_t> at_least;  // lower bound the validator checks (integers)
  std::optional<double> above;           // floats: finite and above this (the validator checks)
};

const std::vector<ParameterField>& run_parameter_fields();

// Present for every model, or only for those that list it (collision_models.h).
bool is_model_specific(const ParameterField& f);
// Present only in the runs that have it: the driven gas's fields, whatever
// the model; the rough particles' inertia; a mixture's species table; a
// model parameter with an `off` value (beta) in the runs of its models that
// are not at it.
bool is_optional(const ParameterField& f);
// The schema version a run's file says: its model's, or that of the driven
// gas, of rough particles or of mixtures if later.
std::int64_t schema_version_of(const RunParameters& p, std::int64_t model_version);
// The field's value as text ("32", "0.1", "inelastic"); nothing when absent.
std::optional<std::string> field_text(const RunParameters& p, const ParameterField& f);

// Writes every field as an attribute of the open /parameters group.
// Throws std::logic_error if a model-specific field is present for a model
// that does not use it, or missing for one that does.
void write_parameters(hid_t group, const RunParameters& p);
// Reads them back; InputError naming `path` and the attribute when one is
// missing or of the wrong type, or the model is unknown. A model-specific
// attribute of a model that does not use it (version 2 wrote r0 = 1 for
// viscoelastic files) is ignored.
// A damaged attribute is an InputError naming it; N must lie in
// [1, kMaxStoredParticles], so no reader allocates for an absurd N.
RunParameters read_parameters(hid_t group, const std::string& path);
// The same from the file's /parameters group (InputError if it is missing or
// cannot be opened).
RunParameters read_file_parameters(hid_t file, const std::string& path);

// The most particles a trajectory holds: particle ids are 32-bit integers.
inline constexpr std::int64_t kMaxStoredParticles = kMaxIndex32;

// The first field of role kPhysics in which a and b differ, e.g.
// "L = 32 vs 48" or "viscoelastic_b = 0.1 vs 0.9"; nothing if none does.
std::optional<std::string> physics_difference(const RunParameters& a, const RunParameters& b);

// The kPhysics fields present, in table order, for a table's provenance block.
Provenance physics_provenance(const RunParameters& p);

}  // namespace coolgas
