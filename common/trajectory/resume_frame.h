// Reading what a resumed run starts from: the last complete dump of a
// trajectory (the completion marker of layout.h), with its counters and the
// run's parameters. Plain arrays: the simulator turns them into engine state
// (simulate/run/resume_point.h).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "common/trajectory/run_parameters.h"

namespace coolgas {

struct ResumeFrame {
  RunParameters params;  // /parameters (scene text included)
  double time = 0;
  std::int64_t collisions = 0, below_delta = 0;  // /restart counters at the dump
  std::size_t particles = 0;                     // N (slots, for aggregation files)
  int dimension = 3;                             // box/dimension: 3, or 2 (disks, z = 0 below)
  std::vector<double> position, velocity;        // 3 per particle, in id order
  std::vector<std::int32_t> image;
  std::vector<double> angular_velocity;  // rough runs only (else empty): 3 per particle
  std::vector<std::int32_t> species;     // mixtures only (else empty): each particle's species
  // aggregation layout only (empty otherwise): slot ids (-1 when absent), masses, diameters
  bool aggregates = false;
  std::vector<std::int32_t> id;
  std::vector<double> mass, diameter;
};

// Throws InputError naming the file ("cannot resume from 'FILE': ...") when
// it is missing, not HDF5, not a coolgas trajectory, holds no complete dump,
// or its arrays do not fit N.
ResumeFrame read_resume_frame(const std::string& path);

}  // namespace coolgas
