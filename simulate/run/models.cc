#include "simulate/run/models.h"

#include <type_traits>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/engine/engine.h"
#include "simulate/engine/state_archive.h"
#include "simulate/run/run_eta.h"
#include "simulate/scene/mixture_rule.h"

namespace coolgas {

namespace {

ElasticRule elastic_rule(const Scene&) { return {}; }
ConstantRestitutionRule inelastic_rule(const Scene& s) { return {s.parameter("r0"), s.parameter("delta")}; }
ViscoelasticRule viscoelastic_rule(const Scene& s) { return {s.parameter("viscoelastic_b"), s.parameter("delta")}; }

// The models whose particles may be rough (collision.beta; engine.cc
// instantiates their rough engines in 2D and 3D): the gases, not aggregation.
template <class Rule>
constexpr bool kMayBeRough = std::is_same_v<Rule, ElasticRule> || std::is_same_v<Rule, ConstantRestitutionRule> ||
                             std::is_same_v<Rule, ViscoelasticRule>;
// The models that may be mixtures ([[species]]; engine.cc instantiates their
// mixture engines in every dimension), the same gases (aggregation's
// mixtures need no rule of their own). The scene refuses a rough mixture.
template <class Rule>
constexpr bool kMayBeMixture = kMayBeRough<Rule>;

// The engine of a collision rule (simulate/engine/collision_rules.h) in the
// scene's dimension: the hot loop is compiled for exactly that rule and D,
// and for rough particles (the scene allows them where they can spin) the
// rough rule's engine, and for a mixture the mixture rule's, so a smooth
// scene of equal particles makes the engine it made before.
template <class Rule, Rule (*rule_of)(const Scene&), class Make>
std::unique_ptr<EngineBase> rule_engine(const Scene& s, const Make& make) {
  return s.geometry().dispatch([&]<int D>() -> std::unique_ptr<EngineBase> {
    if constexpr (kMayBeRough<Rule> && Geometry(D).rotational_axes() > 0) {
      if (s.rough())
        return make.template operator()<D>(RoughRule<Rule>(rule_of(s), s.parameter("beta"), s.particle_inertia()));
    }
    if constexpr (kMayBeMixture<Rule>) {
      if (s.mixture()) return make.template operator()<D>(mixture_rule(s, rule_of(s)));
    }
    return make.template operator()<D>(rule_of(s));
  });
}
template <class Rule, Rule (*rule_of)(const Scene&)>
std::unique_ptr<EngineBase> make_rule_engine(const Scene& s, Particles p, double now, const EngineCounters& c,
                                             const AggregateState*) {
  return rule_engine<Rule, rule_of>(s, [&]<int D, class R>(const R& rule) -> std::unique_ptr<EngineBase> {
    return std::make_unique<Engine<R, D>>(std::move(p), rule, now, c);
  });
}
template <class Rule, Rule (*rule_of)(const Scene&)>
std::unique_ptr<EngineBase> restore_rule_engine(const Scene& s, const StateReader& state) {
  return rule_engine<Rule, rule_of>(s, [&]<int D, class R>(const R& rule) -> std::unique_ptr<EngineBase> {
    return std::make_unique<Engine<R, D>>(rule, state);
  });
}

std::unique_ptr<EngineBase> make_aggregation(const Scene& s, Particles p, double now, const EngineCounters& c,
                                             const AggregateState* aggregates) {
  // A start: unit spheres, or a mixture's particles (each then an aggregate of its species' mass and diameter).
  AggregateState a = aggregates          ? *aggregates
                     : p.species.empty() ? AggregateState::unit_spheres(p.size())
                                         : AggregateState::of_species(p.species, species_masses(s), species_diameters(s));
  return std::make_unique<AggregationEngine>(std::move(p), std::move(a), now, c, s.geometry());
}
// The checkpoint says its dimension; a scene of another one is refused.
std::unique_ptr<EngineBase> restore_aggregation(const Scene& s, const StateReader& state) {
  auto e = std::make_unique<AggregationEngine>(state);
  if (e->geometry() != s.geometry())
    state.fail("a " + std::to_string(e->geometry().d()) + "D aggregation state for a " + std::to_string(s.dimension) +
               "D scene");
  return e;
}

template <class Rule, Rule (*rule_of)(const Scene&)>
ModelRow rule_row(CollisionModel model, RunEta (*eta)(const RunParameters&)) {
  return {model, make_rule_engine<Rule, rule_of>, restore_rule_engine<Rule, rule_of>, eta, &kGasCosts};
}

}  // namespace

const std::vector<ModelRow>& model_rows() {
  static const std::vector<ModelRow> rows = {
      rule_row<ElasticRule, elastic_rule>(CollisionModel::kElastic, eta_without_cooling),
      rule_row<ConstantRestitutionRule, inelastic_rule>(CollisionModel::kInelastic, eta_of_inelastic_gas),
      rule_row<ViscoelasticRule, viscoelastic_rule>(CollisionModel::kViscoelastic, eta_of_cooling_gas),
      {CollisionModel::kAggregation, make_aggregation, restore_aggregation, eta_of_aggregation,
       &kAggregationCosts},
  };
  return rows;
}

const ModelRow& model_row(CollisionModel model) { return model_rows().at(std::size_t(model)); }

RunEta run_eta_for(const RunParameters& p, Geometry g) {
  const ModelRow* row = find_model_row(p.model);
  RunEta eta = p.driving_power ? eta_of_driven_gas(p) : row ? row->eta(p) : eta_of_cooling_gas(p);
  eta.set_dimension(g.d());
  return eta;
}

const ModelRow* find_model_row(std::string_view name) {
  for (const ModelRow& r : model_rows())
    if (name == r.name()) return &r;
  return nullptr;
}

}  // namespace coolgas
