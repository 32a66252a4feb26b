#include "common/trajectory/collision_models.h"

namespace coolgas {

namespace {

const ModelParameter kR0{.name = "r0",
                         .meaning = "coefficient of restitution",
                         .help = "coefficient of restitution",
                         .lo = 0,
                         .hi = 1,
                         .lo_open = true,
                         .default_value = 1.0,
                         .example = 0.5};
const ModelParameter kDelta{.name = "delta",
                            .meaning = "elastic below this normal speed",
                            .help = "cut-off: collisions with normal relative speed below delta are elastic, in "
                                    "units of diameter per initial collision time (the paper uses 1e-4)",
                            .lo = 0,
                            .default_value = 0.0,
                            .example = 1e-3};
const ModelParameter kViscoelasticB{
    .name = "viscoelastic_b",
    .meaning = "viscoelastic material constant b",
    .help = "viscoelastic material constant b = A alpha^{2/5} (Schwager & Poeschel 1998), in units of (diameter "
            "per initial collision time)^(-1/5): r = 1 - 1.15344 b v^(1/5) + 0.79826 b^2 v^(2/5) - ... for normal "
            "impact speed v",
    .lo = 0,
    .lo_open = true,
    .since = 2,
    .example = 0.3};

// Rough spheres (Walton 1993; Huthmann & Zippelius 1997): at a contact the
// tangential relative velocity of the touching surfaces g_t becomes
// -beta g_t. -1 is smooth (the spins never change and are not kept), +1
// perfectly rough (energy conserved with r0 = 1).
const ModelParameter kBeta{.name = "beta",
                           .meaning = "tangential restitution",
                           .help = "tangential coefficient of restitution: the contact points' tangential relative "
                                   "velocity becomes -beta times itself; -1: smooth spheres, 1: perfectly rough "
                                   "(spins kept and turned; in 2D and 3D, see system.inertia)",
                           .lo = -1,
                           .hi = 1,
                           .default_value = -1.0,
                           .off = -1.0,
                           .since = int(kRoughSchemaVersion),
                           .example = 0.4};

}  // namespace

const std::vector<CollisionModelSpec>& collision_models() {
  using layout::Layout;
  // Version 1 files (elastic, inelastic) keep r0 and delta as they always
  // had them; for elastic spheres they are the true values 1 and 0.
  // Version 3 dropped the r0 (and, for aggregation, delta) that version 2
  // wrote for models without a constant restitution.
  static const std::vector<CollisionModelSpec> models = {
      {.name = "elastic",
       .summary = "\"elastic\"",
       .rule = "ElasticRule: the normal relative velocity is reversed (r = 1)",
       .parameters = {&kBeta},
       .fixed = {{&kR0, 1.0}, {&kDelta, 0.0}}},
      {.name = "inelastic",
       .summary = "\"inelastic\" (paper Eq. 1 with the delta cut-off)",
       .rule = "ConstantRestitutionRule: the paper's Eq. (1), r = r0, r = 1 below delta",
       .parameters = {&kR0, &kDelta, &kBeta}},
      {.name = "viscoelastic",
       .summary = "\"viscoelastic\" (restitution rising to 1 as the impact speed falls; see "
                  "collision.viscoelastic_b)",
       .rule = "ViscoelasticRule: r = epsilon(v) from b v^(1/5), r = 1 below delta",
       .parameters = {&kViscoelasticB, &kDelta, &kBeta},
       .schema_version = 3},
      {.name = "aggregation",
       .summary = "\"aggregation\" (ballistic aggregation: spheres that touch merge, volumes add, momentum "
                  "conserved)",
       .rule = "AggregationEngine: spheres that touch merge at their centre of mass",
       .parameters = {},
       .schema_version = 3,
       .layout = Layout::kAggregation},
  };
  return models;
}

const std::vector<const ModelParameter*>& model_parameters() {
  // The order of the scene's collision.* keys (and so of a scene's text, which
  // every file and checkpoint records) and of /parameters.
  static const std::vector<const ModelParameter*> all = {&kR0, &kViscoelasticB, &kDelta, &kBeta};
  return all;
}

const ModelParameter* find_model_parameter(std::string_view name) {
  for (const ModelParameter* p : model_parameters())
    if (p->name == name) return p;
  return nullptr;
}

bool is_rough(const ParameterValues& collision) {
  const auto it = collision.find(kBeta.name);
  return it != collision.end() && it->second != *kBeta.off;
}

const CollisionModelSpec* find_collision_model(std::string_view name) {
  for (const auto& m : collision_models())
    if (m.name == name) return &m;
  return nullptr;
}

bool model_uses(std::string_view model, std::string_view parameter) {
  const CollisionModelSpec* m = find_collision_model(model);
  if (!m) return false;
  for (const ModelParameter* p : m->parameters)
    if (p->name == parameter) return true;
  for (const FixedParameter& f : m->fixed)
    if (f.parameter->name == parameter) return true;
  return false;
}

bool model_keeps_species(std::string_view model) {
  const CollisionModelSpec* m = find_collision_model(model);
  return m && m->layout != layout::Layout::kAggregation;
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
