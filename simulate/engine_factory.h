// Chooses, once at start-up, the engine instantiation for the scene's
// collision model, so the hot loop is compiled for exactly that rule.
#pragma once
#include <memory>

#include "simulate/engine.h"
#include "simulate/scene.h"

namespace coolgas {

std::unique_ptr<EngineBase> make_engine(const Scene& scene, Particles particles, double now,
                                        const EngineCounters& counters = {});

}  // namespace coolgas
