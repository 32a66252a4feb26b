// The engine state to resume from: the last complete dump of a trajectory
// (common/trajectory/resume_frame.h) as particles, counters and aggregates.
#pragma once
#include <optional>
#include <string>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/engine/engine.h"
#include "simulate/engine/particles.h"

namespace coolgas {

struct ResumePoint {
  std::string scene_toml;  // /parameters/scene
  double time = 0;
  EngineCounters counters;  // collisions and below_delta at the dump
  Particles particles;      // positions, velocities, images at `time`
  std::optional<AggregateState> aggregates;  // ids, masses, diameters (aggregation files only)
};

// Throws InputError naming the file when it is missing, not HDF5, not a
// coolgas trajectory, or holds no complete dump.
ResumePoint read_resume_point(const std::string& path);

}  // namespace coolgas
