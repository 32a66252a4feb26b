#include "simulate/run/engine_factory.h"

#include "simulate/run/models.h"

namespace coolgas {

std::unique_ptr<EngineBase> make_engine(const Scene& s, Particles particles, double now,
                                        const EngineCounters& counters, const AggregateState* aggregates) {
  return model_row(s.model).make(s, std::move(particles), now, counters, aggregates);
}

std::unique_ptr<EngineBase> restore_engine(const Scene& s, const StateReader& state) {
  return model_row(s.model).restore(s, state);
}

}  // namespace coolgas
