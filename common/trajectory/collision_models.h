// The collision models as one table: name (the scene's collision.model and
// /parameters/model), the engine rule that implements it, the parameters it
// has beyond the common ones (each the scene key collision.<name> and the
// /parameters attribute <name>, with its meaning, range and default), the
// schema version of its files and its file layout. The scene's collision.*
// keys, the /parameters fields (common/trajectory/run_parameters.h) and what
// a checkpoint records as physics are all made from this table. A parameter
// a model does not list is absent from its files: "not applicable" is never
// written as a sentinel value.
//
// Adding a model: a row here, its rule and its row in simulate/ (ARCHITECTURE.md).
#pragma once
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/trajectory/layout.h"

namespace coolgas {

// A model-specific parameter. Models that share a parameter (delta) share
// its row, so the key has one meaning, range and default.
struct ModelParameter {
  std::string_view name;     // collision.<name> in a scene, <name> in /parameters
  std::string_view meaning;  // a few words, for /parameters and tables' provenance
  std::string_view help;     // the scene key's --help text: meaning and units
  // lo <= x <= hi, strict where *_open; every value must be finite.
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  std::optional<double> default_value;  // none: a scene of the model must give it
  // The value at which the parameter's effect is off (beta = -1: smooth
  // spheres): a scene's text and a run's file leave it out there, so those
  // of runs without the effect stay what they were before it existed.
  std::optional<double> off;
  int since = 1;                        // the schema version that added the attribute
  double example = 0;                   // a typical value (the engine contract test runs with it)
};

// A parameter a model's files carry at a value no scene sets: elastic
// spheres' files keep r0 = 1 and delta = 0, as version 1 always wrote them.
struct FixedParameter {
  const ModelParameter* parameter;
  double value;
};

struct CollisionModelSpec {
  std::string_view name;
  std::string_view summary;  // collision.model's --help: what the model does
  std::string_view rule;     // simulate/engine/collision_rules.h or the engine it needs
  std::vector<const ModelParameter*> parameters;  // the scene sets them
  std::vector<FixedParameter> fixed = {};         // in its files only
  std::int64_t schema_version = 1;                // data-schema/h5md-profile.md
  layout::Layout layout = layout::Layout::kGas;
};

const std::vector<CollisionModelSpec>& collision_models();

// Every model-specific parameter once (a test checks that each model's are
// here): the order of the scene's collision.* keys and of /parameters.
const std::vector<const ModelParameter*>& model_parameters();

// The parameter row of `name`, or nullptr for a name no model has.
const ModelParameter* find_model_parameter(std::string_view name);

// The row of `name`, or nullptr for a model this build does not know.
const CollisionModelSpec* find_collision_model(std::string_view name);

// Whether files of `model` hold the model-specific attribute `parameter`
// (false for an unknown model).
bool model_uses(std::string_view model, std::string_view parameter);

// Whether a mixture's particles keep their species through a run of
// `model`: not in ballistic aggregation, whose aggregates merge particles of
// several species (their mass and diameter say what they are). False for an
// unknown model.
bool model_keeps_species(std::string_view model);

// "elastic, inelastic, viscoelastic, aggregation"
std::string collision_model_names();

// Values of model-specific parameters by name, as a scene or a file has them.
using ParameterValues = std::map<std::string, double, std::less<>>;

// Rough spheres (collision.beta > -1): files carry beta, the particles'
// inertia, their angular velocities and the rotational energy, and say this
// schema version or later (data-schema/h5md-profile.md).
inline constexpr std::int64_t kRoughSchemaVersion = 5;
// Whether values of a run's parameters make its particles rough.
bool is_rough(const ParameterValues& collision);

}  // namespace coolgas
