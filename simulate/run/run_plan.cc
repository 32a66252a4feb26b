#include "simulate/run/run_plan.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "common/error.h"
#include "simulate/engine/engine_base.h"
#include "simulate/run/engine_factory.h"
#include "simulate/run/run_eta.h"
#include "simulate/run/scene_file.h"
#include "simulate/run/time_grid.h"
#include "simulate/start/initial_state.h"

namespace coolgas {

namespace {

// What a collision, a merge, a particle and a dump cost on this project's
// machine (the table of current figures in tests/bench/README.md names the
// commands), per CPU second of whole runs, set-up and dumps included.
// The gas: 3.497e7 collisions in 52.9 CPU-s (L = 68, N = 1.3e5, to t = 1e4)
// and 7.815e7 in 192.0 (L = 136, N = 1e6, to t = 1e3); larger grids miss
// the cache more often.
constexpr double kCollisionsPerSecondSmall = 6.61e5, kCollisionsPerSecondLarge = 4.07e5;
constexpr double kSmallRunParticles = 1.3e5;
// Aggregation at N = 8e6 to t = 1e5 (the aggregation_bench): merges per
// second and the set-up (a dilute start places and equilibrates slower),
// interpolated in ln phi between the two densities measured.
constexpr double kDensePhi = 0.208, kDilutePhi = 0.005;
constexpr double kMergesPerSecondDense = 35971, kMergesPerSecondDilute = 12813;
constexpr double kSetupSecondsDense = 153.2, kSetupSecondsDilute = 688.5, kSetupParticles = 8e6;
constexpr double kAggregationBytesPerParticle = 187;  // peak at N = 1e6 (the gas: kBytesPerParticle)
// A dump's compressed size per particle: the gas's largest measured (late,
// clustered: 47 at L = 34, t = 1e5); aggregation adds id, mass and diameter,
// counted at the gas's compression (47 + 20 x 42/61).
constexpr double kDumpBytesGas = 47, kDumpBytesAggregation = 62;
constexpr double kRequestExtraBytes = 256e6;  // the libraries and the output buffers

constexpr std::int64_t kPilotEventsPerSlice = std::int64_t(1) << 30;  // far below the budget's overflow

bool is_aggregation(const Scene& s) { return s.model == CollisionModel::kAggregation; }

// The scene at kPilotParticles, at the same phi and everything else.
Scene pilot_scene(const Scene& scene) {
  if (scene.N <= kPilotParticles) return scene;
  return parse_scene(scene.to_toml(), "the pilot of the scene", {"system.N=" + std::to_string(kPilotParticles)});
}

// The pilot's collisions at its log-spaced times up to t_stop, scaled to
// the run's N, fed to `eta`; returns the last time reached (earlier than
// t_stop if the pilot stopped: a collapse, an aggregate too large).
double run_pilot(const Scene& pilot, double scale, double t_stop, RunEta& eta, InterruptFlag interrupt) {
  std::unique_ptr<EngineBase> engine = make_engine(pilot, initial_state(pilot, interrupt), 0.0);
  std::vector<double> times = log_grid(pilot.t_min, t_stop, 20);
  times.push_back(t_stop);
  double reached = 0;
  for (double t : times) {
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

double cpu_seconds(const Scene& s, double collisions) {
  if (!is_aggregation(s)) {
    const double rate = double(s.N) <= kSmallRunParticles ? kCollisionsPerSecondSmall : kCollisionsPerSecondLarge;
    return (collisions + s.equilibrate * double(s.N) / 2) / rate;
  }
  const double f = std::log(s.phi / kDilutePhi) / std::log(kDensePhi / kDilutePhi);
  const double merges = std::exp(std::log(kMergesPerSecondDilute) + f * std::log(kMergesPerSecondDense / kMergesPerSecondDilute));
  const double setup = std::exp(std::log(kSetupSecondsDilute) + f * std::log(kSetupSecondsDense / kSetupSecondsDilute));
  return collisions / merges + double(s.N) / kSetupParticles * setup;
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
  const double t_stop = std::min(scene.t_end, kPilotTime);
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
  plan.cpu_seconds = cpu_seconds(scene, plan.collisions);
  plan.peak_bytes = double(scene.N) * (is_aggregation(scene) ? kAggregationBytesPerParticle : kBytesPerParticle);
  plan.dumps = dumps_of(scene);
  plan.disk_bytes = plan.dumps * double(scene.N) * (is_aggregation(scene) ? kDumpBytesAggregation : kDumpBytesGas);
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
