// Chooses, once at start-up, the engine instantiation for the scene's
// collision model, so the hot loop is compiled for exactly that rule; a
// scene with [driving] gets it wrapped in the kicks (simulate/engine/driving.h).
#pragma once
#include <memory>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/engine/engine.h"
#include "simulate/engine/state_archive.h"
#include "simulate/scene/scene.h"

namespace coolgas {

// `aggregates` (aggregation only; resume): the slots' masses, diameters and
// ids; by default every particle is a unit sphere.
std::unique_ptr<EngineBase> make_engine(const Scene& scene, Particles particles, double now,
                                        const EngineCounters& counters = {},
                                        const AggregateState* aggregates = nullptr);

// The engine of the scene's model with the exact state `state` holds (a checkpoint).
std::unique_ptr<EngineBase> restore_engine(const Scene& scene, const StateReader& state);

}  // namespace coolgas
