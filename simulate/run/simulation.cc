#include "simulate/run/simulation.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/error.h"
#include "common/fault_point.h"
#include "common/interrupt.h"
#include "common/trajectory/collision_models.h"
#include "common/trajectory/h5md_writer.h"
#include "common/trajectory/writer_lock.h"
#include "data-schema/validator.h"
#include "common/output_file.h"
#include "common/progress.h"
#include "simulate/run/eta_gate.h"
#include "simulate/run/models.h"
#include "simulate/run/run_eta.h"
#include "common/tsv.h"
#include "simulate/run/checkpoint.h"
#include "simulate/run/engine_factory.h"
#include "simulate/start/file_start.h"
#include "simulate/start/initial_state.h"
#include "simulate/run/resume_point.h"
#include "simulate/run/scene_file.h"
#include "simulate/run/time_grid.h"

namespace coolgas {

namespace {

// Events between progress and checkpoint checks: small enough for a lively
// display, large enough that the check costs nothing.
constexpr std::int64_t kEventsPerSlice = 1 << 20;

// Wall-clock seconds between periodic checkpoints (what a SIGKILL can cost
// at most); COOLGAS_CHECKPOINT_INTERVAL overrides it. A checkpoint of
// 10^5 particles is ~15 MB: at this interval it costs far below 1 %
// (the checkpoint row of tests/bench/README.md).
constexpr double kCheckpointInterval = 300;

double checkpoint_interval() {
  const char* s = std::getenv("COOLGAS_CHECKPOINT_INTERVAL");
  if (!s || !*s) return kCheckpointInterval;
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if (*end != '\0' || !(v >= 0))
    throw InputError(std::string("COOLGAS_CHECKPOINT_INTERVAL = '") + s +
                     "' is not a number of seconds >= 0 (unset it for the default of 300)");
  return v;
}

ObservableRow row_of(const Observables& o) {
  ObservableRow row{o.time, o.collisions, o.below_delta, o.kinetic_energy, {o.momentum.x, o.momentum.y, o.momentum.z}};
  if (o.aggregates) {
    row.aggregates = o.aggregates->aggregates;
    row.mean_mass = o.aggregates->mean_mass;
    row.largest_mass = o.aggregates->largest_mass;
  }
  row.rotational_energy = o.rotational_energy.value_or(0.0);
  if (o.species_energy.size() > row.species_energy.size()) throw std::logic_error("more species than a file holds");
  std::copy(o.species_energy.begin(), o.species_energy.end(), row.species_energy.begin());
  return row;
}

// The writer's view of a frame (which must outlive it).
FrameView view_of(const EngineFrame& f) {
  FrameView v{f.time, f.collisions, f.below_delta, &f.position[0].x, f.image[0].data(), &f.velocity[0].x, 3, 3};
  if (!f.id.empty()) {
    v.id = f.id.data();
    v.mass = f.mass.data();
    v.diameter = f.diameter.data();
  }
  if (!f.angular_velocity.empty()) v.angular_velocity = &f.angular_velocity[0].x;
  if (!f.species.empty()) v.species = f.species.data();
  return v;
}

// Drives the engine from stop to stop, writing as it goes.
class Driver {
 public:
  // `interval`: wall-clock seconds between periodic checkpoints.
  Driver(const Scene& scene, EngineBase& engine, H5mdWriter& writer, std::string path, bool quiet, double interval)
      : scene_(scene), engine_(engine), writer_(writer), path_(std::move(path)),
        e0_(initial_energy(scene)), progress_(!quiet), interval_(interval),
        last_checkpoint_(clock::now()) {}

  // A resumed run: the file holds every output up to `written` (its last
  // dump); `pending` are the observables after the checkpoint's own last
  // dump, up to the engine's time.
  void resume_after(double written, const std::vector<ObservableRow>& pending) {
    written_ = last_dump_ = written;
    for (const ObservableRow& row : pending) record(row);
  }

  int run() {
    const double t0 = engine_.now();
    const std::int64_t c0 = engine_.counters().collisions;
    const std::vector<StopTime> stops = stop_times(scene_);
    dump_times_left_.clear();
    for (const StopTime& s : stops)
      if (s.dump && s.t > written_) dump_times_left_.push_back(s.t);
    for (const StopTime& stop : stops) {
      if (stop.t < t0) continue;  // (a stop at t0 itself may be due: a checkpoint is taken before its stop)
      if (!advance_to(stop.t)) return finish_interrupted();
      if (stop.observe) record(row_of(engine_.observables()));
      if (stop.dump) dump();
    }
    writer_.flush();
    checkpoint();  // so that extending run.t_end continues exactly
    report_rate(c0);
    return kExitOk;
  }

  // The first dump of a new run, and its checkpoint.
  void start() {
    record(row_of(engine_.observables()));
    dump();
  }
  void checkpoint() {
    const auto start = clock::now();
    write_checkpoint(path_, scene_, engine_, last_dump_, pending_);
    last_checkpoint_ = clock::now();
    checkpoint_cost_.add(seconds_since(start));
  }

  // Called when the engine cannot go on: its state is written as the last dump.
  int finish_stopped(const std::string& message) {
    record(row_of(engine_.observables()));
    dump();
    std::cerr << "coolgas-simulate: error: " << message << " (the state at t = " << engine_.now()
              << " is written as the last dump)\n";
    return kExitCollapse;
  }

 private:
  using clock = std::chrono::steady_clock;
  static double seconds_since(clock::time_point start) {
    return std::chrono::duration<double>(clock::now() - start).count();
  }

  // One row of observables, unless the file holds it already.
  void record(const ObservableRow& row) {
    if (row.time <= written_) return;
    writer_.add_observables(row);
    pending_.push_back(row);
  }

  // A frame at the engine's time (the engine itself is not touched).
  void dump() {
    const double t = engine_.now();
    if (t > written_) {
      const auto start = clock::now();
      const EngineFrame f = engine_.frame();
      writer_.add_frame(view_of(f));
      dump_cost_.add(seconds_since(start), eta_.frame_size(t));
      auto& left = dump_times_left_;
      left.erase(left.begin(), std::upper_bound(left.begin(), left.end(), t));
    }
    last_dump_ = t;
    pending_.clear();
  }

  bool advance_to(double t) {
    while (true) {
      const auto slice_start = clock::now();
      // A test's fault after K events ends a slice there: the engine stops at
      // its budget exactly, so nothing is added to its per-event loop.
      const std::int64_t budget = std::min(kEventsPerSlice, fault_events_left(events_done()));
      const RunStatus status = engine_.run_until(t, budget, interrupt_flag());
      busy_seconds_ += seconds_since(slice_start);
      fault_after_events(events_done());
      if (status == RunStatus::kInterrupted) return false;
      if (seconds_since(last_checkpoint_) >= interval_) checkpoint();
      show_progress();
      if (status == RunStatus::kReached) return true;
    }
  }

  int finish_interrupted() {
    writer_.flush();
    checkpoint();
    std::cerr << "\ncoolgas-simulate: interrupted by " << signal_name(interrupt_signal()) << " at t = " << engine_.now()
              << "; checkpoint written, continue with --resume\n";
    return kExitInterrupted;
  }

  // The rate shown counts only the seconds spent in the engine; the ETA adds
  // the dumps and checkpoints still due (simulate/run/run_eta.h).
  void show_progress() {
    const double t = engine_.now(), coll = double(engine_.counters().collisions);
    eta_.add({t, coll, busy_seconds_, double(engine_.counters().events)});
    if (!progress_.due()) return;
    const double engine_left = eta_.seconds_left(scene_.t_end);
    std::vector<double> dump_sizes;
    for (double at : dump_times_left_) dump_sizes.push_back(eta_.frame_size(at));
    const double left =
        engine_left + output_seconds_left(dump_sizes, engine_left, interval_, dump_cost_, checkpoint_cost_);
    const double elapsed = progress_.elapsed();
    std::ostringstream s;
    s.precision(3);
    s << "t = " << t << " / " << scene_.t_end << " (" << std::lround(100 * log_clock(t)) << " % of log t)  collisions "
      << coll << " (" << eta_.collision_rate() << "/s)  E/E0 = " << engine_.observables().kinetic_energy / e0_
      << "  elapsed " << Progress::format_duration(elapsed) << "  left ";
    if (eta_gate_.show(elapsed, left))
      s << "~" << Progress::format_duration(left) << " (" << std::lround(100 * elapsed / (elapsed + left)) << " % done)";
    else
      s << "estimating...";
    progress_.show(s.str());
  }

  // Events this process has run (a test's fault counts them: common/fault_point.h).
  std::int64_t events_done() const { return engine_.counters().events - first_event_; }

  // How far t is from t = 0 to t_end on the run's logarithmic clock, in [0, 1]
  // (its dumps and observables are log-spaced in t).
  double log_clock(double t) const { return std::clamp(std::log1p(t) / std::log1p(scene_.t_end), 0.0, 1.0); }

  void report_rate(std::int64_t c0) {
    if (!progress_.due() && progress_.elapsed() < 1) return;
    std::ostringstream s;
    s.precision(3);
    const double n = double(engine_.counters().collisions - c0);
    s << "done: t = " << engine_.now() << ", " << n << " collisions in " << progress_.elapsed() << " s ("
      << n / std::max(busy_seconds_, 1e-9) << "/s in the engine, dumps excluded)";
    progress_.show(s.str());
  }

  const Scene& scene_;
  EngineBase& engine_;
  H5mdWriter& writer_;
  std::string path_;
  double e0_;
  Progress progress_;
  RunEta eta_ = run_eta_for(parameters_of(scene_), scene_.geometry());
  EtaGate eta_gate_;
  double busy_seconds_ = 0;  // wall seconds inside the engine (no dumps, no checkpoints)
  OutputCost dump_cost_, checkpoint_cost_;
  std::vector<double> dump_times_left_;  // the dumps of the run still to write, in time order
  double interval_;
  clock::time_point last_checkpoint_;
  double written_ = -1;    // the file holds every output up to this time
  double last_dump_ = -1;  // the time of the file's last complete dump
  std::int64_t first_event_ = engine_.counters().events;
  std::vector<ObservableRow> pending_;  // observables written after that dump
};

std::string default_output(const std::string& scene_path) {
  return std::filesystem::path(scene_path).stem().string() + ".h5";
}

// Checked before the (possibly long) set-up, so a typo costs nothing.
void check_writable(const std::string& out, bool force) { check_output_file(out, force, "--resume it"); }

// A file another coolgas-simulate is writing is never replaced: that writer
// would go on into an unlinked file, and its checkpoints would overwrite
// this run's. The lock, held until the new file takes the old one's place,
// also keeps a --resume of the old file from starting meanwhile.
WriterLock lock_replaced_file(const std::string& out, bool force) {
  std::error_code ec;
  if (!force || !std::filesystem::is_regular_file(out, ec)) return {};
  return WriterLock::take(out);
}

// A file the validator rejects is refused before a byte of it changes:
// frames appended to it would hide the damage, and its state is no sound
// start. (Rows of a burst a kill cut short are not damage: the resume drops
// them.) Called after the resume point is read, whose messages name the
// field a damaged file fails on.
void check_valid_to_resume(const std::string& path) {
  const schema::Report report = schema::validate(path);
  if (report.valid()) return;
  const auto& first = report.problems.front();
  const std::size_t more = report.problems.size() - 1;
  throw InputError("cannot resume '" + path + "': " + first.path + ": " + first.what +
                   (more ? " (" + std::to_string(more) + " more: coolgas-validate lists them)" : ""));
}

int drive(Driver& driver, const Scene& scene) {
  try {
    return driver.run();
  } catch (const RunStopped& e) {
    // Collapse stops only models with a cut-off (collision_models.h); aggregation outgrows its box.
    const double delta = e.reason == StopReason::kAggregateTooLarge ? 0 : scene.parameter("delta");
    const std::string hint = e.reason == StopReason::kAggregateTooLarge ? ""
                             : delta > 0 ? "; increase collision.delta (now " + format_number(delta) + ")"
                                         : "; set collision.delta > 0 (the paper uses 1e-4)";
    return driver.finish_stopped(e.what() + hint);
  }
}

// The new run's file under its temporary name. Creating it can fail after
// the file appeared (a full disk: HDF5 opens it, then cannot write its
// superblock), so a failure removes what is there: a run that fails to
// start leaves nothing behind.
H5mdWriter create_partial(const std::string& tmp, const Scene& scene) {
  try {
    return H5mdWriter::create(tmp, parameters_of(scene), true, scene.geometry());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

int start_new(const SimulationRequest& req) {
  Scene scene = parse_scene(read_scene_file(req.scene_path), req.scene_path, req.overrides);
  if (!scene.size_note.empty()) std::cerr << "coolgas-simulate: note: " << scene.size_note << "\n";
  const double interval = checkpoint_interval();
  const std::string out = req.output.empty() ? default_output(req.scene_path) : req.output;
  check_writable(out, req.force);
  WriterLock replaced = lock_replaced_file(out, req.force);
  std::unique_ptr<EngineBase> engine;
  if (scene.init == InitialPositions::kFile) {
    FileStart start = start_from_file(scene);
    scene = start.scene;  // completed from the file (N, L, phi, T0)
    if (!req.quiet) std::cerr << "coolgas-simulate: " << start.notice << "\n";
    engine = make_engine(scene, std::move(start.particles), 0.0, {}, start.aggregates ? &*start.aggregates : nullptr);
  } else {
    try {
      Progress setup(!req.quiet);  // placement and equilibration take seconds to minutes at large N
      const auto report = [&](const std::string& line, bool phase) {
        if (phase || setup.due())
          setup.show("set-up (" + Progress::format_duration(setup.elapsed()) + "): " + line);
      };
      engine = make_engine(scene, initial_state(scene, interrupt_flag(), report), 0.0);
    } catch (const SetupInterrupted&) {
    }
  }
  if (interrupted()) {
    std::cerr << "coolgas-simulate: interrupted by " << signal_name(interrupt_signal())
              << " during set-up; nothing written\n";
    return kExitInterrupted;
  }
  // Write the first dump to a temporary name and move it into place only
  // then: a run that fails to start leaves no file, and --force replaces an
  // old file only with a readable new one. An old run's checkpoint goes
  // first, so it can never be taken for this run's.
  const std::string tmp = out + ".partial";
  H5mdWriter writer = create_partial(tmp, scene);
  Driver driver(scene, *engine, writer, out, req.quiet, interval);
  // The checkpoint (replacing an old run's at once) is in place before the
  // trajectory: from the moment the file exists, resume is exact from any
  // stop. (A kill between the two renames leaves an old run's file, if any,
  // beside this run's checkpoint: the same physics and seed, as the
  // checkpoint's check of the physics ensures, so the same t = 0 state.)
  try {
    driver.start();
    driver.checkpoint();
    writer.rename(out);  // errors from here on name the real output
    replaced = WriterLock();  // the replaced file's space is freed now, not at the end of the run
  } catch (...) {
    std::filesystem::remove(tmp);
    remove_checkpoint(out);
    throw;
  }
  return drive(driver, scene);
}

int resume(const SimulationRequest& req) {
  for (const auto& o : req.overrides) {
    const std::string key = o.substr(0, o.find('='));
    if (!key_changeable_on_resume(key))
      throw InputError("--set " + key + " cannot change on --resume: only run.* and output.* keys can");
  }
  const double interval = checkpoint_interval();
  // Before the file is read: a second --resume of it is refused at once.
  WriterLock lock = H5mdWriter::claim(req.resume);
  ResumePoint rp = read_resume_point(req.resume);
  const Scene scene = parse_scene(rp.scene_toml, req.resume + ":/parameters/scene", req.overrides);
  check_valid_to_resume(req.resume);
  if (rp.time >= scene.t_end) {
    // Killed after its last dump, the file still has the killed writer's
    // "open for writing" flags: opening it to append and closing it clears
    // them, so that every program reads it.
    H5mdWriter::reopen(req.resume, nullptr, std::move(lock));
    std::cerr << "coolgas-simulate: '" << req.resume << "' already reached run.t_end = " << scene.t_end
              << "; nothing to do (extend it with --set run.t_end=...)\n";
    return kExitOk;
  }
  // The checkpoint when there is one (exact), else the last dump (the same
  // physics, but not the same trajectory bit for bit).
  std::optional<RunCheckpoint> ck = read_checkpoint(req.resume, scene);
  if (ck && ck->last_dump > rp.time)
    throw InputError("cannot resume '" + req.resume + "': its checkpoint follows a dump at t = " +
                     format_number(ck->last_dump) + " that the file does not hold (last dump t = " +
                     format_number(rp.time) + "); remove '" + checkpoint_path(req.resume) +
                     "' to resume from the last dump");
  std::unique_ptr<EngineBase> engine =
      ck ? std::move(ck->engine)
         : make_engine(scene, std::move(rp.particles), rp.time, rp.counters, rp.aggregates ? &*rp.aggregates : nullptr);
  if (!ck && !req.quiet)
    std::cerr << "coolgas-simulate: no checkpoint '" << checkpoint_path(req.resume)
              << "'; continuing from the last dump (not bit-identical to an uninterrupted run)\n";
  // The stored scene changes only when the overrides change it (a reopen
  // that changes it copies the file: h5md_writer.h).
  const std::string text = scene.to_toml();
  const bool changed = text != parse_scene(rp.scene_toml, req.resume + ":/parameters/scene", {}).to_toml();
  H5mdWriter writer = H5mdWriter::reopen(req.resume, changed ? &text : nullptr, std::move(lock));
  Driver driver(scene, *engine, writer, req.resume, req.quiet, interval);
  driver.resume_after(rp.time, ck ? ck->pending : std::vector<ObservableRow>{});
  return drive(driver, scene);
}

}  // namespace

int run_simulation(const SimulationRequest& req) {
  // Installed first, so a signal during set-up is noticed (a shell starts
  // background jobs with SIGINT ignored, and the default would leave no message).
  watch_interrupts();
  const std::string fault = armed_fault();  // armed by run_tool (common/tool_main.h)
  if (!fault.empty() && !req.quiet) std::cerr << "coolgas-simulate: note: COOLGAS_FAULT = '" << fault << "' (a test's fault)\n";
  return req.resume.empty() ? start_new(req) : resume(req);
}

}  // namespace coolgas
