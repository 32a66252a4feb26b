// A start from a frame of a file (system.init = "file"): the configuration
// of simulate/start/configuration_file.h made into the state at t = 0, and
// the scene completed from it.
//
// - N and L come from the file (ballistic aggregates: one particle per
//   aggregate present, ids renumbered 0..N-1 in the file's order), phi is
//   the fraction of the box its particles cover; any of N, L, phi the scene
//   gives must agree with the file. Its dimension (a 2D box of disks, a
//   ring of rods) must be system.dimension.
// - Diameters other than 1 only for collision.model = "aggregation"
//   (masses: the file's, else d^D; diameters: the file's, else m^(1/D)).
// - Velocities from the file, else Maxwellian at T0 (zero total momentum,
//   temperature exactly T0) from system.seed.
// - T0, which sets the time unit: system.T0 if given, else a coolgas
//   trajectory's own (its times go on in its unit) or the T0= of an
//   extended XYZ comment line (coolgas-convert writes it), else the Enskog value
//   of the file's density, as for a fresh start.
// - The configuration is checked (simulate/start/configuration_check.h):
//   an overlapping pair is named with its distance, a particle outside the
//   box [0, L) with its position.
#pragma once
#include <optional>
#include <string>

#include "simulate/engine/aggregation_engine.h"
#include "simulate/engine/particles.h"
#include "simulate/scene/scene.h"

namespace coolgas {

struct FileStart {
  Scene scene;  // the scene completed from the file: N, L, phi, T0 and from_time
  Particles particles;
  std::optional<AggregateState> aggregates;  // collision.model = "aggregation"
  std::string notice;  // one line saying what was read, for stderr
};

// Reads scene.from and completes the scene from it: N, L, phi, T0 and
// from_time (the frame's time, when the file has one). Throws InputError
// (one line).
FileStart start_from_file(const Scene& scene);

}  // namespace coolgas
