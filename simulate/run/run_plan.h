// The plan of a run before it starts (coolgas-simulate --estimate), for a
// scheduler's request and a study's plan (make estimate in
// pipelines/workstation and pipelines/paper): its particles, memory, dumps,
// disk and CPU time.
//
// The CPU time comes from the same cost model as the progress line's time
// left (run_eta.h), so that the two cannot disagree: a pilot of the scene
// (the same gas at kPilotParticles, or the run itself if smaller) is
// simulated to t = min(t_end, kPilotTime) and on while it is cheap
// (kPilotCollisionsPerParticle), its collisions, scaled to the
// run's N, are fed to the run's own RunEta as a run's samples would be, and
// its extrapolation to t_end gives the collisions (aggregation: merges)
// expected. Before the finite-size crossover the collisions per particle do
// not depend on the box, so the pilot's small box stands for the large one;
// the run's own box sets where the crossover comes. The collisions then cost
// a measured number of CPU seconds each (run_plan.cc, with the runs that
// measured them).
#pragma once
#include <string>

#include "common/interrupt.h"
#include "simulate/scene/scene.h"

namespace coolgas {

inline constexpr std::int64_t kPilotParticles = 10000;
inline constexpr double kPilotTime = 100;  // a whole fit window of run_eta.h (t/3 .. t) past the first collisions
// Past kPilotTime the pilot goes on towards t_end, up to kPilotTimeMost and
// the finite-size knee of its own box, while it has done fewer collisions
// than kPilotCollisionsPerParticle: a gas whose collisions change course
// there (rods clustering, disks leaving t^1.2) is seen doing it, for about a
// CPU second at most (a pilot of the 3D gas: 0.3 s to t = 100, 0.6 s to 300).
inline constexpr double kPilotTimeMost = 300;
inline constexpr double kPilotCollisionsPerParticle = 200;
// The pilot's equilibration at most, in collision times (the scene's
// default): enough for an equilibrium fluid; the run's own equilibration is
// priced analytically (run_plan.cc says why).
inline constexpr double kPilotEquilibrate = 5;
inline constexpr double kRequestMargin = 1.5;  // a request's memory and time over the expected

struct RunPlan {
  double L = 0;
  std::int64_t N = 0;
  double collisions = 0;   // expected by t_end after t = 0 (aggregation: merges)
  double cpu_seconds = 0;  // set-up and engine, expected
  double peak_bytes = 0;   // the run's memory at its peak
  int dumps = 0;           // frames written, t = 0 and t_end included
  double disk_bytes = 0;   // the trajectory's size at the end
};

// The plan of `scene` (not a start from a file, which cannot be scaled down
// to a pilot: InputError). Looks at `interrupt` while the pilot runs, its
// set-up included: Interrupted (exit code 3) within a fraction of a second.
RunPlan plan_run(const Scene& scene, InterruptFlag interrupt);

// The plan as a header and a line of tab-separated columns: L N mem_GB
// hours dumps disk_GB peak_GB cpu_h collisions (mem_GB and hours with the
// margin of a request, whole GB; peak_GB and cpu_h without).
std::string plan_header();
std::string plan_line(const RunPlan& plan);

}  // namespace coolgas
