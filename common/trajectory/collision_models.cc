#include "common/trajectory/collision_models.h"

namespace coolgas {

const std::vector<CollisionModelSpec>& collision_models() {
  using layout::Layout;
  // Version 1 files (elastic, inelastic) keep r0 and delta as they always
  // had them; for elastic spheres they are the true values 1 and 0.
  // Version 3 dropped the r0 (and, for aggregation, delta) that version 2
  // wrote for models without a constant restitution.
  static const std::vector<CollisionModelSpec> models = {
      {"elastic", "ElasticRule: the normal relative velocity is reversed (r = 1)", {"r0", "delta"}, 1, Layout::kGas},
      {"inelastic", "ConstantRestitutionRule: the paper's Eq. (1), r = r0, r = 1 below delta", {"r0", "delta"}, 1,
       Layout::kGas},
      {"viscoelastic", "ViscoelasticRule: r = epsilon(v) from b v^(1/5), r = 1 below delta",
       {"viscoelastic_b", "delta"}, 3, Layout::kGas},
      {"aggregation", "AggregationEngine: spheres that touch merge at their centre of mass", {}, 3,
       Layout::kAggregation},
  };
  return models;
}

const CollisionModelSpec* find_collision_model(std::string_view name) {
  for (const auto& m : collision_models())
    if (m.name == name) return &m;
  return nullptr;
}

bool model_uses(std::string_view model, std::string_view parameter) {
  const CollisionModelSpec* m = find_collision_model(model);
  if (!m) return false;
  for (std::string_view p : m->parameters)
    if (p == parameter) return true;
  return false;
}

std::string collision_model_names() {
  std::string s;
  for (const auto& m : collision_models()) {
    if (!s.empty()) s += ", ";
    s += m.name;
  }
  return s;
}

}  // namespace coolgas
