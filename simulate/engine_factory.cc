#include "simulate/engine_factory.h"

namespace coolgas {

std::unique_ptr<EngineBase> make_engine(const Scene& s, Particles particles, double now,
                                        const EngineCounters& counters) {
  switch (s.model) {
    case CollisionModel::kElastic:
      return std::make_unique<Engine<ElasticRule>>(std::move(particles), ElasticRule{}, now, counters);
    case CollisionModel::kInelastic:
      return std::make_unique<Engine<ConstantRestitutionRule>>(std::move(particles),
                                                               ConstantRestitutionRule{s.r0, s.delta}, now, counters);
  }
  return nullptr;
}

}  // namespace coolgas
