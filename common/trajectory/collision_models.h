// The collision models as one table: name (the scene's collision.model and
// /parameters/model), the engine rule that implements it, the /parameters
// attributes it has beyond the common ones, the schema version of its files
// and its file layout. A parameter a model does not list is absent from its
// files: "not applicable" is never written as a sentinel value.
//
// Adding a model: a row here, its rule in simulate/engine/ (ARCHITECTURE.md).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/trajectory/layout.h"

namespace coolgas {

struct CollisionModelSpec {
  std::string_view name;
  std::string_view rule;                     // simulate/engine/collision_rules.h or the engine it needs
  std::vector<std::string_view> parameters;  // model-specific /parameters attributes (run_parameters.h)
  std::int64_t schema_version = 1;           // data-schema/h5md-profile.md
  layout::Layout layout = layout::Layout::kGas;
};

const std::vector<CollisionModelSpec>& collision_models();

// The row of `name`, or nullptr for a model this build does not know.
const CollisionModelSpec* find_collision_model(std::string_view name);

// Whether files of `model` hold the model-specific attribute `parameter`
// (false for an unknown model).
bool model_uses(std::string_view model, std::string_view parameter);

// "elastic, inelastic, viscoelastic, aggregation"
std::string collision_model_names();

}  // namespace coolgas
