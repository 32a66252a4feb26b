// When a run stops to record: observables and dumps on log-spaced grids
// (data-schema/h5md-profile.md, "Dump times").
#pragma once
#include <vector>

#include "simulate/scene/scene.h"

namespace coolgas {

// 10^(k/per_decade) for every integer k with t_min <= 10^(k/per_decade) < t_end.
std::vector<double> log_grid(double t_min, double t_end, int per_decade);

struct StopTime {
  double t;
  bool observe;  // record a row of observables
  bool dump;     // write a trajectory frame (a restart point)
};

// Every stop after t = 0 up to and including run.t_end, in increasing time.
std::vector<StopTime> stop_times(const Scene& scene);

}  // namespace coolgas
