#include "simulate/run/engine_factory.h"

namespace coolgas {

namespace {

// Calls make(rule) with the scene's collision rule, or make_aggregation()
// for ballistic aggregation: the one place that maps a model to its engine.
template <class Make, class MakeAggregation>
std::unique_ptr<EngineBase> by_model(const Scene& s, Make&& make, MakeAggregation&& make_aggregation) {
  switch (s.model) {
    case CollisionModel::kElastic: return make(ElasticRule{});
    case CollisionModel::kInelastic: return make(ConstantRestitutionRule{s.r0, s.delta});
    case CollisionModel::kViscoelastic: return make(ViscoelasticRule{s.viscoelastic_b, s.delta});
    case CollisionModel::kAggregation: return make_aggregation();
  }
  return nullptr;
}

}  // namespace

std::unique_ptr<EngineBase> make_engine(const Scene& s, Particles particles, double now,
                                        const EngineCounters& counters, const AggregateState* aggregates) {
  return by_model(
      s,
      [&](const auto& rule) -> std::unique_ptr<EngineBase> {
        using Rule = std::decay_t<decltype(rule)>;
        return std::make_unique<Engine<Rule>>(std::move(particles), rule, now, counters);
      },
      [&]() -> std::unique_ptr<EngineBase> {
        AggregateState a = aggregates ? *aggregates : AggregateState::unit_spheres(particles.size());
        return std::make_unique<AggregationEngine>(std::move(particles), std::move(a), now, counters);
      });
}

std::unique_ptr<EngineBase> restore_engine(const Scene& s, const StateReader& state) {
  return by_model(
      s,
      [&](const auto& rule) -> std::unique_ptr<EngineBase> {
        using Rule = std::decay_t<decltype(rule)>;
        return std::make_unique<Engine<Rule>>(rule, state);
      },
      [&]() -> std::unique_ptr<EngineBase> { return std::make_unique<AggregationEngine>(state); });
}

}  // namespace coolgas
