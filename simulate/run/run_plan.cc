#include "simulate/run/run_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "common/error.h"
#include "simulate/engine/engine_base.h"
#include "simulate/run/engine_factory.h"
#include "simulate/run/models.h"
#include "simulate/run/run_eta.h"
#include "simulate/run/scene_file.h"
#include "simulate/run/time_grid.h"
#include "simulate/start/initial_state.h"

namespace coolgas {

namespace {

constexpr double kRequestExtraBytes = 256e6;  // the libraries and the output buffers

constexpr std::int64_t kPilotEventsPerSlice = std::int64_t(1) << 30;  // far below the budget's overflow

// The scene at kPilotParticles, at the same phi and everything else but
// its equilibration, which is cut to kPilotEquilibrate collision times.
// Why not simulate it all: the pilot measures how often the particles of an
// equilibrium fluid collide after t = 0, and the fluid is in equilibrium
// after a few collision times (the scene's default, 5); a longer
// equilibration changes which configuration the run starts from, not its
// statistics, so the pilot's collisions stay what they were. Its cost,
// however, grows without bound (system.equilibrate = 1e7 is 5e10 collisions
// of the pilot's 10^4 particles: hours, in a command promising seconds), and
// the plan needs none of it: the cost model adds the run's own equilibration
// analytically, equilibrate x N / 2 collisions at the run's rate
// (run_costs.cc).
Scene pilot_scene(const Scene& scene) {
  Scene pilot = scene.N <= kPilotParticles
                    ? scene
                    : parse_scene(scene.to_toml(), "the pilot of the scene",
                                  {"system.N=" + std::to_string(kPilotParticles)});
  pilot.equilibrate = std::min(pilot.equilibrate, kPilotEquilibrate);
  return pilot;
}

// The pilot's collisions at its log-spaced times up to t_stop, scaled to
// the run's N, fed to `eta`; returns the last time reached (earlier than
// t_stop past kPilotTime once its collisions reach the budget, or if the
// pilot stopped: a collapse, an aggregate too large).
double run_pilot(const Scene& pilot, double scale, double t_stop, RunEta& eta, InterruptFlag interrupt) {
  std::unique_ptr<EngineBase> engine;
  try {
    engine = make_engine(pilot, initial_state(pilot, interrupt), 0.0);
  } catch (const SetupInterrupted&) {  // the normal interrupted exit (3), as a run's set-up has
    throw Interrupted(int(*interrupt), "in the set-up of the pilot run of --estimate; nothing written");
  }
  std::vector<double> times = log_grid(pilot.t_min, t_stop, 20);
  times.push_back(t_stop);
  double reached = 0;
  const double budget = kPilotCollisionsPerParticle * double(pilot.N);
  for (double t : times) {
    if (t > kPilotTime && double(engine->counters().collisions) >= budget) break;
    try {
      RunStatus status;
      while ((status = engine->run_until(t, kPilotEventsPerSlice, interrupt)) == RunStatus::kEventBudget) {
      }
      if (status == RunStatus::kInterrupted) throw_if_interrupted("in the pilot run of --estimate");
    } catch (const RunStopped&) {
      return reached;
    }
    reached = t;
    eta.add({t, double(engine->counters().collisions) * scale, 0, NAN});
  }
  return reached;
}

int dumps_of(const Scene& s) {
  int dumps = 1;  // t = 0
  for (const StopTime& stop : stop_times(s)) dumps += stop.dump ? 1 : 0;
  return dumps;
}

}  // namespace

RunPlan plan_run(const Scene& scene, InterruptFlag interrupt) {
  if (scene.init == InitialPositions::kFile)
    throw InputError("--estimate needs a generated start (system.init = \"random\" or \"fcc\"): a start from a file "
                     "cannot be scaled down to a pilot run");
  const Scene pilot = pilot_scene(scene);
  RunEta eta = run_eta_for(parameters_of(scene), scene.geometry());
  const double t_stop = std::min({scene.t_end, kPilotTimeMost, std::max(kPilotTime, eta.knee(pilot.L))});
  const double reached = run_pilot(pilot, double(scene.N) / double(pilot.N), t_stop, eta, interrupt);
  if (!(reached > 0))
    throw InputError("the pilot run of this scene stopped before its first sample (an inelastic collapse or an "
                     "aggregate too large): the run itself would stop too");
  const double expected = eta.expected_collisions(scene.t_end);
  RunPlan plan;
  plan.L = scene.L;
  plan.N = scene.N;
  // Without an extrapolation (a pilot stopped early, no merge in its window), the collisions seen so far.
  plan.collisions = std::isfinite(expected) ? expected : eta.expected_collisions(reached);
  const ModelCosts& costs = *model_row(scene.model).costs;
  plan.cpu_seconds = costs.cpu_seconds(scene, plan.collisions);
  plan.peak_bytes = double(scene.N) * costs.bytes_per_particle;
  plan.dumps = dumps_of(scene);
  plan.disk_bytes = plan.dumps * double(scene.N) * costs.dump_bytes_per_particle;
  return plan;
}

std::string plan_header() { return "L\tN\tmem_GB\thours\tdumps\tdisk_GB\tpeak_GB\tcpu_h\tcollisions"; }

std::string plan_line(const RunPlan& p) {
  const int mem_gb = int((kRequestMargin * p.peak_bytes + kRequestExtraBytes) / 1e9) + 1;
  char line[256];
  std::snprintf(line, sizeof line, "%.6g\t%lld\t%d\t%.2f\t%d\t%.1f\t%.2f\t%.4f\t%.4g", p.L, (long long)p.N, mem_gb,
                kRequestMargin * p.cpu_seconds / 3600, p.dumps, p.disk_bytes / 1e9, p.peak_bytes / 1e9,
                p.cpu_seconds / 3600, p.collisions);
  return line;
}

}  // namespace coolgas
