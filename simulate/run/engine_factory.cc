#include "simulate/run/engine_factory.h"

#include "simulate/engine/driving.h"
#include "simulate/run/models.h"
#include "simulate/start/initial_state.h"

namespace coolgas {

namespace {

// The scene's [driving] (the scene allows it only for the models whose
// engines can be kicked); the kicks' noise is seeded by the run's seed. The
// scene gives the power in T0 per initial collision time, the engine takes
// it in m sigma^2 omega0^3, where T0 is initial_temperature (1/(pi (4 n chi)^2)
// in 3D, not 1).
Driving driving_of(const Scene& s) {
  return {.power = *s.driving_power * initial_temperature(s), .period = s.driving_period, .seed = std::uint64_t(s.seed),
          .geometry = s.geometry()};
}

}  // namespace

std::unique_ptr<EngineBase> make_engine(const Scene& s, Particles particles, double now,
                                        const EngineCounters& counters, const AggregateState* aggregates) {
  auto engine = model_row(s.model).make(s, std::move(particles), now, counters, aggregates);
  if (!s.driving_power) return engine;
  return std::make_unique<DrivenEngine>(std::move(engine), driving_of(s));
}

std::unique_ptr<EngineBase> restore_engine(const Scene& s, const StateReader& state) {
  auto engine = model_row(s.model).restore(s, state);
  if (!s.driving_power) return engine;
  return std::make_unique<DrivenEngine>(std::move(engine), driving_of(s), state);
}

}  // namespace coolgas
