// Engine speed: collisions per second of wall time on one core (set-up
// excluded) and memory per particle, for the workloads of the simulator issue:
//   W1  elastic,               N = 108000, phi = 0.208
//   W2  r0 = 0.1, delta = 1e-3, N = 108000, phi = 0.208
//   W1R W1 with perfectly rough spheres (collision.beta = 1, inertia 2/5: the
//       energy is kept, spins drawn at T0): the rough rule's own cost
//   W1M W1 as a binary mixture (half diameter 1, mass 1; half diameter 1.5,
//       mass 3.375; phi = 0.208 in all): the mixture rule's own cost
// each from the Gaussian start for 50 collisions per particle, and
//   W5  elastic,               N = 10^6,   phi = 0.208, 20 collisions per particle
//   W5D2 as W5 with hard disks (system.dimension = 2), area fraction 0.208
//   W5D1 as W5 with hard rods on a ring (system.dimension = 1), line fraction 0.208
//   W7  the paper's gas, r0 = 0.1, delta = 1e-4, N = 8x10^6, phi = 0.208, 5 collisions
//       per particle from a clustered state: the L = 68 gas (N = 125000) run
//       from its Gaussian start to t = 1000, tiled 4x4x4 (a valid periodic
//       configuration of L = 272), clock restarted at 0. Set-up and the
//       homogeneous phase are left out, as in the paper's long runs. The L = 68
//       state is made once (a few minutes) and kept next to this program
//       (w7_clustered_N125000_t1000.state; delete it to make it again).
// Rates are given per second of wall time and per second of this process's
// CPU time: on an idle machine they agree; on a shared one the CPU figure is
// the engine's own speed.
// usage: engine_bench [W1|W2|all|W1R|W1M|W5|W5D2|W5D1|W7] [N] [collisions_per_particle] [repeats] [checkpoint_seconds]
// (W5 and W7 take their own N and collisions per particle unless given;
// W7's N must be 64 times a tiled state's)
// (repeats: runs of each workload, then a line with the best, median and worst;
// checkpoint_seconds > 0: a checkpoint of the run (simulate/run/checkpoint.h)
// is written that often, to a scratch file under /tmp, so that the cost of
// the periodic checkpoint is measured as a ratio against 0)
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "simulate/engine/engine.h"
#include "simulate/run/checkpoint.h"
#include "simulate/scene/mixture_rule.h"
#include "simulate/start/initial_state.h"
#include "tests/bench/process_stats.h"

namespace {

using coolgas::bench::cpu_seconds;
using coolgas::bench::status_bytes;

// The engine of a workload, as its concrete class (the calendar statistic
// is a benchmark hook of the class, not of the runner's view).
template <class Rule>
std::unique_ptr<coolgas::Engine<Rule>> engine_for(const coolgas::Scene& s, const Rule& rule) {
  return std::make_unique<coolgas::Engine<Rule>>(coolgas::initial_state(s), rule, 0.0);
}

// W7's start: the state of `base` (a Gaussian start) at time t_base, made
// once and kept in `path` (positions and velocities in id order), then
// repeated k x k x k times. A periodic configuration of L is one of k L, so
// the tiled gas has the same contacts and clusters, k^3 times over.
std::string g_program_dir = ".";

// Particles at the given positions and velocities, all at time 0.
coolgas::Particles at_time_zero(double L, std::vector<coolgas::Vec3> r, std::vector<coolgas::Vec3> v) {
  coolgas::Particles p;
  p.L = L;
  p.r = std::move(r);
  p.v = std::move(v);
  p.t.assign(p.r.size(), 0.0);
  p.image.assign(p.r.size(), coolgas::Image{0, 0, 0});
  return p;
}

template <class Rule>
coolgas::Particles clustered_base(const coolgas::Scene& base, const Rule& rule, double t_base) {
  const std::string path = g_program_dir + "/w7_clustered_N" + std::to_string(base.N) + "_t1000.state";
  std::ifstream in(path, std::ios::binary);
  if (in) {
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const coolgas::StateReader r(std::move(bytes), path);
    coolgas::Particles p =
        at_time_zero(r.get_value<double>("L"), r.get<coolgas::Vec3>("position"), r.get<coolgas::Vec3>("velocity"));
    if (p.size() == std::size_t(base.N) && p.L == base.L) return p;
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto e = engine_for(base, rule);
  while (e->now() < t_base) e->run_until(t_base, 1 << 22, nullptr);
  const coolgas::EngineFrame f = e->frame();
  std::fprintf(stderr, "W7: made the clustered start (N=%lld, L=%.4f, t=%g, %lld collisions) in %.0f s -> %s\n",
               (long long)base.N, base.L, f.time, (long long)f.collisions,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), path.c_str());
  const std::string tmp = path + ".part";
  if (std::FILE* out = std::fopen(tmp.c_str(), "wb")) {
    coolgas::StateWriter w(out);
    w.put_value("L", base.L);
    w.put("position", f.position);
    w.put("velocity", f.velocity);
    w.finish();
    std::fclose(out);
    std::rename(tmp.c_str(), path.c_str());
  }
  return at_time_zero(base.L, f.position, f.velocity);
}

coolgas::Particles tiled(const coolgas::Particles& b, int k) {
  coolgas::Particles p;
  p.L = b.L * k;
  const std::size_t n = b.size();
  p.resize(n * std::size_t(k) * k * k);
  std::size_t at = 0;
  for (int a = 0; a < k; ++a)
    for (int c = 0; c < k; ++c)
      for (int d = 0; d < k; ++d)
        for (std::size_t i = 0; i < n; ++i, ++at) {
          const coolgas::Vec3 shift{a * b.L, c * b.L, d * b.L};
          for (int x = 0; x < 3; ++x) {
            p.r[at][x] = b.r[i][x] + shift[x];
            if (p.r[at][x] >= p.L) p.r[at][x] -= p.L;  // rounding at the far face
          }
          p.v[at] = b.v[i];
          p.t[at] = 0.0;
          p.image[at] = coolgas::Image{0, 0, 0};
        }
  return p;
}

// One run from a fresh start; prints its line and returns collisions per
// second of wall time.
double g_checkpoint_seconds = 0;

template <class Rule, class Make>
double run(const char* name, const coolgas::Scene& s, const Make& make, double per_particle) {
  using clock = std::chrono::steady_clock;
  // What the process holds before any particle exists (code, libraries):
  // subtracted so the figure is the simulation's own bytes per particle.
  const double baseline = status_bytes("VmRSS:");
  const auto t_setup = clock::now();
  const auto e = make();  // an Engine<Rule, D>
  const double setup = std::chrono::duration<double>(clock::now() - t_setup).count();
  const auto target = static_cast<std::int64_t>(per_particle * double(s.N) / 2.0);  // two particles per collision
  const auto t0 = clock::now();
  const double cpu0 = cpu_seconds();
  const std::string scratch = "/tmp/engine_bench_" + std::to_string(getpid()) + ".h5";
  auto last_checkpoint = clock::now();
  int checkpoints = 0;
  while (e->counters().collisions < target) {
    e->run_until(e->now() * 1.05 + 0.1, 1 << 20, nullptr);
    if (g_checkpoint_seconds > 0 &&
        std::chrono::duration<double>(clock::now() - last_checkpoint).count() >= g_checkpoint_seconds) {
      coolgas::write_checkpoint(scratch, s, *e, 0.0, {});
      last_checkpoint = clock::now();
      ++checkpoints;
    }
  }
  if (checkpoints > 0) std::remove(coolgas::checkpoint_path(scratch).c_str());
  const double secs = std::chrono::duration<double>(clock::now() - t0).count();
  const double cpu = cpu_seconds() - cpu0;
  const auto& c = e->counters();
  std::printf("%s\tN=%lld\tphi=%.3f\tcollisions=%lld\tt=%.4g\twall=%.2fs\tcollisions/s=%.0f\tper_cpu_s=%.0f"
              "\tevents/collision=%.2f\tstale/collision=%.2f\tpeak_bytes/particle=%.0fB\tsetup=%.2fs\tcalendar_years=%lld"
              "\tcheckpoints=%d\n",
              name, (long long)s.N, s.phi, (long long)c.collisions, e->now(), secs, double(c.collisions) / secs,
              double(c.collisions) / cpu,
              double(c.events) / double(c.collisions), double(c.stale) / double(c.collisions),
              (status_bytes("VmHWM:") - baseline) / double(s.N), setup, (long long)e->calendar_years(), checkpoints);
  std::fflush(stdout);
  return double(c.collisions) / secs;
}

// One run in a child process, so that each run's peak memory is its own
// (freed memory the allocator keeps would count against the next run).
template <class Rule, class Make>
double run_apart(const char* name, const coolgas::Scene& s, const Make& make, double per_particle) {
  int fd[2];
  if (pipe(fd) != 0) return run<Rule>(name, s, make, per_particle);
  std::fflush(stdout);  // or the child would print the parent's buffered lines again
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    const double rate = run<Rule>(name, s, make, per_particle);
    const bool sent = write(fd[1], &rate, sizeof rate) == ssize_t(sizeof rate);
    _exit(sent ? 0 : 1);
  }
  close(fd[1]);
  double rate = 0;
  const bool got = read(fd[0], &rate, sizeof rate) == ssize_t(sizeof rate);
  close(fd[0]);
  waitpid(pid, nullptr, 0);
  return got ? rate : 0.0;
}

// Repeats a workload: on a shared machine single runs vary by up to ±20 %;
// the best of several is the engine's speed with the least interference.
template <class Rule, class Make>
void repeat(const char* name, const coolgas::Scene& s, const Make& make, double per_particle, int times) {
  std::vector<double> rates;
  for (int k = 0; k < times; ++k) rates.push_back(run_apart<Rule>(name, s, make, per_particle));
  std::sort(rates.begin(), rates.end());
  std::printf("%s	summary of %d runs	best=%.0f	median=%.0f	worst=%.0f collisions/s\n", name, times, rates.back(),
              rates[rates.size() / 2], rates.front());
}

template <class Rule>
void repeat(const char* name, const coolgas::Scene& s, const Rule& rule, double per_particle, int times) {
  repeat<Rule>(name, s, [&] { return engine_for(s, rule); }, per_particle, times);
}

coolgas::Scene workload(bool inelastic, std::int64_t n, double delta = 1e-3) {
  coolgas::Scene s;
  s.N = n;
  s.phi = 0.208;
  s.L = std::cbrt(double(n) * M_PI / (6.0 * s.phi));
  s.t_end = 1e9;
  if (inelastic) {
    s.model = coolgas::CollisionModel::kInelastic;
    s.set_parameter("r0", 0.1);
    s.set_parameter("delta", delta);
  }
  return s;
}

// W5's gas as hard disks: the same N and covered fraction in a square.
coolgas::Scene disk_workload(std::int64_t n) {
  coolgas::Scene s = workload(false, n);
  s.dimension = 2;
  s.L = std::sqrt(double(n) * M_PI / (4.0 * s.phi));
  return s;
}

// W5's gas as hard rods: the same N and covered fraction on a ring.
coolgas::Scene rod_workload(std::int64_t n) {
  coolgas::Scene s = workload(false, n);
  s.dimension = 1;
  s.L = double(n) / s.phi;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "all";
  const bool w5 = which == "W5" || which == "W5D2" || which == "W5D1", w7 = which == "W7";
  const std::int64_t n = argc > 2 ? std::atoll(argv[2]) : w5 ? 1000000 : w7 ? 8000000 : 108000;
  const double per = argc > 3 ? std::atof(argv[3]) : w5 ? 20 : w7 ? 5 : 50;
  const int times = argc > 4 ? std::atoi(argv[4]) : 1;
  g_checkpoint_seconds = argc > 5 ? std::atof(argv[5]) : 0;
  if (which == "W1" || which == "all") repeat("W1", workload(false, n), coolgas::ElasticRule{}, per, times);
  if (which == "W2" || which == "all")
    repeat("W2", workload(true, n), coolgas::ConstantRestitutionRule{0.1, 1e-3}, per, times);
  if (which == "W1R") {
    coolgas::Scene s = workload(false, n);
    s.set_parameter("beta", 1.0);  // initial_state draws the spins
    repeat("W1R", s, coolgas::RoughRule<coolgas::ElasticRule>({}, 1.0, s.particle_inertia()), per, times);
  }
  if (which == "W1M") {
    coolgas::Scene s = workload(false, n);
    s.species = {{0.5, 1.0, std::nullopt}, {0.5, 1.5, std::nullopt}};
    s.L = s.geometry().box_side_for(s.unit_particles(), s.phi);
    repeat("W1M", s, coolgas::mixture_rule(s, coolgas::ElasticRule{}), per, times);
  }
  if (which == "W5") repeat("W5", workload(false, n), coolgas::ElasticRule{}, per, times);
  if (which == "W5D2") {
    const coolgas::Scene s = disk_workload(n);
    repeat<coolgas::ElasticRule>(
        "W5D2", s,
        [&] { return std::make_unique<coolgas::Engine<coolgas::ElasticRule, 2>>(coolgas::initial_state(s), coolgas::ElasticRule{}, 0.0); },
        per, times);
  }
  if (which == "W5D1") {
    const coolgas::Scene s = rod_workload(n);
    repeat<coolgas::ElasticRule>(
        "W5D1", s,
        [&] { return std::make_unique<coolgas::Engine<coolgas::ElasticRule, 1>>(coolgas::initial_state(s), coolgas::ElasticRule{}, 0.0); },
        per, times);
  }
  if (w7) {
    constexpr int k = 4;
    const std::string prog = argv[0];
    g_program_dir = prog.find('/') == std::string::npos ? "." : prog.substr(0, prog.rfind('/'));
    const coolgas::ConstantRestitutionRule rule{0.1, 1e-4};
    const coolgas::Scene base = workload(true, n / (k * k * k), 1e-4);
    coolgas::Scene s = workload(true, n, 1e-4);
    s.L = base.L * k;
    // Made outside the timed runs (and before the children fork): a fresh
    // process then only reads and tiles it.
    const coolgas::Particles b = clustered_base(base, rule, 1000.0);
    repeat<coolgas::ConstantRestitutionRule>(
        "W7", s, [&] { return std::make_unique<coolgas::Engine<coolgas::ConstantRestitutionRule>>(tiled(b, k), rule, 0.0); },
        per, times);
  }
}
