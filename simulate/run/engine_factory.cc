#include "simulate/run/engine_factory.h"

namespace coolgas {

std::unique_ptr<EngineBase> make_engine(const Scene& s, Particles particles, double now,
                                        const EngineCounters& counters, const AggregateState* aggregates) {
  switch (s.model) {
    case CollisionModel::kElastic:
      return std::make_unique<Engine<ElasticRule>>(std::move(particles), ElasticRule{}, now, counters);
    case CollisionModel::kInelastic:
      return std::make_unique<Engine<ConstantRestitutionRule>>(std::move(particles),
                                                               ConstantRestitutionRule{s.r0, s.delta}, now, counters);
    case CollisionModel::kViscoelastic:
      return std::make_unique<Engine<ViscoelasticRule>>(std::move(particles),
                                                        ViscoelasticRule{s.viscoelastic_b, s.delta}, now, counters);
    case CollisionModel::kAggregation: {
      AggregateState a = aggregates ? *aggregates : AggregateState::unit_spheres(particles.size());
      return std::make_unique<AggregationEngine>(std::move(particles), std::move(a), now, counters);
    }
  }
  return nullptr;
}

}  // namespace coolgas
