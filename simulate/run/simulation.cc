#include "simulate/run/simulation.h"

#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/error.h"
#include "common/h5md_writer.h"
#include "common/output_file.h"
#include "common/progress.h"
#include "common/tsv.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/initial_state.h"
#include "simulate/run/resume_point.h"
#include "simulate/run/time_grid.h"

namespace coolgas {

namespace {

volatile std::sig_atomic_t g_interrupt = 0;
extern "C" void on_signal(int sig) { g_interrupt = sig; }

void install_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

// Events between progress checks: small enough for a lively display, large
// enough that the check costs nothing.
constexpr std::int64_t kEventsPerSlice = 1 << 20;

std::string read_file(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw InputError("cannot read scene '" + path + "' (missing or unreadable)");
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

ObservableRow observe(const EngineBase& e) {
  if (e.masses()) {  // aggregation: masses differ, and the aggregate observables are asked for
    const AggregateSummary a = summarize_aggregates(e);
    ObservableRow row{e.now(), e.counters().collisions, e.counters().below_delta, a.kinetic_energy,
                      {a.momentum.x, a.momentum.y, a.momentum.z}};
    row.aggregates = a.aggregates;
    row.mean_mass = a.mean_mass;
    row.largest_mass = a.largest_mass;
    return row;
  }
  const Vec3 p = total_momentum(e);
  return {e.now(), e.counters().collisions, e.counters().below_delta, kinetic_energy_per_particle(e), {p.x, p.y, p.z}};
}

FrameView frame(const EngineBase& e) {
  const Motion* m = e.motion();
  FrameView f{e.now(),    e.counters().collisions, e.counters().below_delta, &m[0].r.x, e.images()[0].data(),
              &m[0].v.x, kMotionStride,           kMotionStride};
  f.id = e.ids();  // all three nullptr unless the model is aggregation
  f.mass = e.masses();
  f.diameter = e.diameters();
  return f;
}

// Drives the engine from stop to stop, writing as it goes.
class Driver {
 public:
  Driver(const Scene& scene, EngineBase& engine, H5mdWriter& writer, double e0, bool quiet)
      : scene_(scene), engine_(engine), writer_(writer), e0_(e0), progress_(!quiet) {}

  int run() {
    const double t0 = engine_.now();
    const std::int64_t c0 = engine_.counters().collisions;
    for (const StopTime& stop : stop_times(scene_)) {
      if (stop.t <= t0) continue;
      if (!advance_to(stop.t)) return finish_interrupted();
      if (stop.observe) writer_.add_observables(observe(engine_));
      if (stop.dump) {
        engine_.synchronize();
        writer_.add_frame(frame(engine_));
      }
    }
    writer_.flush();
    report_rate(c0);
    return kExitOk;
  }

  // Called after a CollapseError (or an aggregate too large for the box):
  // the state is made consistent and dumped.
  int finish_collapsed(const std::string& message) {
    engine_.synchronize();
    writer_.add_observables(observe(engine_));
    writer_.add_frame(frame(engine_));
    std::cerr << "coolgas-simulate: error: " << message << " (the state at t = " << engine_.now()
              << " is written as the last dump)\n";
    return kExitCollapse;
  }

 private:
  bool advance_to(double t) {
    while (true) {
      switch (engine_.run_until(t, kEventsPerSlice, &g_interrupt)) {
        case RunStatus::kReached: show_progress(); return true;
        case RunStatus::kInterrupted: return false;
        case RunStatus::kEventBudget: show_progress(); break;
      }
    }
  }

  int finish_interrupted() {
    engine_.synchronize();
    writer_.add_observables(observe(engine_));
    writer_.add_frame(frame(engine_));
    std::cerr << "\ncoolgas-simulate: interrupted by signal " << int(g_interrupt) << " at t = " << engine_.now()
              << "; final dump written, continue with --resume\n";
    return kExitInterrupted;
  }

  void show_progress() {
    if (!progress_.due()) return;
    const double t = engine_.now(), secs = progress_.elapsed();
    const double coll = double(engine_.counters().collisions);
    // The stops are log-spaced, so progress is measured in log(1 + t).
    const double done = std::log1p(t) / std::log1p(scene_.t_end);
    const double eta = done > 0 ? secs * (1 - done) / done : 0;
    std::ostringstream s;
    s.precision(3);
    s << "t = " << t << " / " << scene_.t_end << "  collisions " << coll << " (" << coll / std::max(secs, 1e-9)
      << "/s)  E/E0 = " << observe(engine_).kinetic_energy / e0_ << "  ETA ~"
      << Progress::format_duration(eta);
    progress_.show(s.str());
  }

  void report_rate(std::int64_t c0) {
    if (!progress_.due() && progress_.elapsed() < 1) return;
    std::ostringstream s;
    s.precision(3);
    const double n = double(engine_.counters().collisions - c0);
    s << "done: t = " << engine_.now() << ", " << n << " collisions in " << progress_.elapsed() << " s";
    progress_.show(s.str());
  }

  const Scene& scene_;
  EngineBase& engine_;
  H5mdWriter& writer_;
  double e0_;
  Progress progress_;
};

RunParameters parameters_of(const Scene& s) {
  RunParameters p;
  p.scene_toml = s.to_toml();
  p.seed = s.seed;
  p.N = s.N;
  p.L = s.L;
  p.phi = s.phi;
  p.T0 = initial_temperature(s);
  p.model = s.model_name();
  p.r0 = s.model == CollisionModel::kAggregation ? 0.0 : s.r0;  // aggregates keep no relative velocity
  p.delta = s.delta;
  p.viscoelastic_b = s.viscoelastic_b;
  return p;
}

std::string default_output(const std::string& scene_path) {
  return std::filesystem::path(scene_path).stem().string() + ".h5";
}

// Checked before the (possibly long) set-up, so a typo costs nothing.
void check_writable(const std::string& out, bool force) { check_output_file(out, force); }

int drive(const Scene& scene, EngineBase& engine, H5mdWriter& writer, bool quiet) {
  Driver driver(scene, engine, writer, 1.5 * initial_temperature(scene), quiet);
  try {
    return driver.run();
  } catch (const CollapseError& e) {
    const std::string hint = scene.model == CollisionModel::kAggregation ? ""
                             : scene.delta > 0 ? "; increase collision.delta (now " + format_number(scene.delta) + ")"
                                               : "; set collision.delta > 0 (the paper uses 1e-4)";
    return driver.finish_collapsed(e.what() + hint);
  }
}

int start_new(const SimulationRequest& req) {
  const Scene scene = parse_scene(read_file(req.scene_path), req.scene_path, req.overrides);
  const std::string out = req.output.empty() ? default_output(req.scene_path) : req.output;
  check_writable(out, req.force);
  auto engine = make_engine(scene, initial_state(scene), 0.0);
  if (g_interrupt) {
    std::cerr << "coolgas-simulate: interrupted by signal " << int(g_interrupt) << " during set-up; nothing written\n";
    return kExitInterrupted;
  }
  // Write the first dump to a temporary name and move it into place only
  // then: a run that fails to start leaves no file, and --force replaces an
  // old file only with a readable new one.
  const std::string tmp = out + ".partial";
  H5mdWriter writer = H5mdWriter::create(tmp, parameters_of(scene), true);
  try {
    writer.add_observables(observe(*engine));
    writer.add_frame(frame(*engine));
    std::filesystem::rename(tmp, out);
  } catch (...) {
    std::filesystem::remove(tmp);
    throw;
  }
  return drive(scene, *engine, writer, req.quiet);
}

int resume(const SimulationRequest& req) {
  for (const auto& o : req.overrides) {
    const std::string key = o.substr(0, o.find('='));
    if (!key_changeable_on_resume(key))
      throw InputError("--set " + key + " cannot change on --resume: only run.* and output.* keys can");
  }
  ResumePoint rp = read_resume_point(req.resume);
  const Scene scene = parse_scene(rp.scene_toml, req.resume + ":/parameters/scene", req.overrides);
  if (rp.time >= scene.t_end) {
    std::cerr << "coolgas-simulate: '" << req.resume << "' already reached run.t_end = " << scene.t_end
              << "; nothing to do (extend it with --set run.t_end=...)\n";
    return kExitOk;
  }
  auto engine = make_engine(scene, std::move(rp.particles), rp.time, rp.counters,
                            rp.aggregates ? &*rp.aggregates : nullptr);
  H5mdWriter writer = H5mdWriter::reopen(req.resume);
  writer.update_scene(scene.to_toml());
  return drive(scene, *engine, writer, req.quiet);
}

}  // namespace

int run_simulation(const SimulationRequest& req) {
  // Installed first, so a signal during set-up is noticed (a shell starts
  // background jobs with SIGINT ignored, and the default would leave no message).
  install_signal_handlers();
  return req.resume.empty() ? start_new(req) : resume(req);
}

}  // namespace coolgas
