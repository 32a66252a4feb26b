#include "analyze/smoluchowski/run.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <ostream>

#include "analyze/smoluchowski/initial.h"
#include "analyze/smoluchowski/kernel.h"
#include "analyze/smoluchowski/solve.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/memory.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

Convention parse_convention(const std::string& name) {
  if (name == "half") return Convention::HalfGain;
  if (name == "paper") return Convention::Paper;
  throw InputError("time convention '" + name + "' is not known; use half (½ on the gain term) or paper (Eq. 3)");
}


namespace {

// Stop for --until-mean-mass without --t-end: far beyond any useful run.
constexpr double kUntilCap = 1e12;

// Half-gain time per unit of the chosen convention.
double time_factor(Convention c) { return c == Convention::Paper ? 2.0 : 1.0; }

void require_time(double t, const std::string& what) {
  if (!(t >= 0) || !std::isfinite(t))
    throw InputError(what + " must be a finite time >= 0, got " + format_number(t));
}

}  // namespace

void validate(const RunOptions& o) {
  validate(o.method);
  for (double t : o.times) require_time(t, "output time (--times)");
  if (o.t_end) require_time(*o.t_end, "end time (--t-end)");
  if (o.times.empty() && !o.t_end && !o.until_mean_mass)
    throw InputError("nothing to do: give --t-end, --times or --until-mean-mass");
  if (o.until_mean_mass && !(*o.until_mean_mass > 1 && *o.until_mean_mass < double(o.method.M)))
    throw InputError("target mean mass (--until-mean-mass) must lie between 1 and the cut-off M = " +
                     std::to_string(o.method.M) + ", got " + format_number(*o.until_mean_mass));
  if (!(o.series_t_min > 0) || !std::isfinite(o.series_t_min))
    throw InputError("first series time (--series-t-min) must be > 0, got " + format_number(o.series_t_min));
  if (o.series_per_decade < 1)
    throw InputError("series points per decade must be >= 1, got " + std::to_string(o.series_per_decade));
  if (!(o.volume > 0) || !std::isfinite(o.volume))
    throw InputError("system volume (--volume) must be > 0, got " + format_number(o.volume));
  if (!(o.leak_tolerance > 0)) throw InputError("leak tolerance must be > 0, got " + format_number(o.leak_tolerance));
  if (o.series && !o.series_file.empty())
    throw InputError("--series (series on stdout) and --series-file exclude each other; pick one");
}

double run_bytes(const RunOptions& o, const Kernel& kernel) {
  const double cells = grid_cells(o.method);
  // The state before a step and a crossing's two copies (refine_crossing);
  // a table's start by mass (1 to M) besides its cells on the grid.
  const double copies = 3 * cells + (o.initial == "mono" ? 0.0 : double(o.method.M) + 1);
  return method_bytes(kernel, o.method) + integrator_bytes(cells, o.integrator.stepper) + copies * sizeof(double);
}

void check_run_memory(const RunOptions& o, const Kernel& kernel, double memory_bytes) {
  const double need = run_bytes(o, kernel);
  if (need <= memory_bytes) return;
  // The largest M that fits: the bytes grow with M.
  RunOptions fit = o;
  std::int64_t lo = 1, hi = o.method.M;
  while (hi - lo > 1) {
    fit.method.M = lo + (hi - lo) / 2;
    (run_bytes(fit, kernel) <= memory_bytes ? lo : hi) = fit.method.M;
  }
  throw InputError("cut-off mass --M " + std::to_string(o.method.M) + " would need " + bytes_text(need) +
                   " (method " + method_name(o.method.method) + ", kernel '" + o.kernel + "'); the memory available is " +
                   bytes_text(memory_bytes) + ": --M at most " + (lo >= 2 ? std::to_string(lo) : std::string("1 (none)")));
}

namespace {

struct Checkpoint {
  double t;  // ½-gain time
  bool distribution = false, series = false;
};

// Every time at which something is written, in ½-gain time, merged and sorted.
std::vector<Checkpoint> schedule(const RunOptions& o, bool want_series, double t_stop) {
  const double f = time_factor(o.convention);
  std::vector<Checkpoint> cps;
  for (double t : o.times)
    if (t * f <= t_stop) cps.push_back({t * f, true, false});
  cps.push_back({t_stop, true, want_series});
  if (want_series) {
    cps.push_back({0, false, true});
    for (int k = 0;; ++k) {
      const double t = o.series_t_min * std::pow(10.0, double(k) / o.series_per_decade) * f;
      if (t >= t_stop) break;
      cps.push_back({t, false, true});
    }
  }
  std::sort(cps.begin(), cps.end(), [](const Checkpoint& a, const Checkpoint& b) { return a.t < b.t; });
  std::vector<Checkpoint> merged;
  for (const auto& c : cps) {
    if (!merged.empty() && merged.back().t == c.t) {
      merged.back().distribution |= c.distribution;
      merged.back().series |= c.series;
    } else {
      merged.push_back(c);
    }
  }
  return merged;
}

Provenance provenance(const RunOptions& o, const Kernel& k, const MassGrid& g) {
  Provenance p{{"kernel", k.text},
               {"kernel_terms", k.as_separable() + "  (K = sum c (i^p j^q + i^q j^p))"},
               {"method", method_name(o.method.method)},
               {"M", std::to_string(o.method.M)},
               {"grid_cells", std::to_string(g.size())}};
  if (o.method.method == Method::Geometric) p.push_back({"grid_ratio", format_number(o.method.grid_ratio)});
  if (o.method.method == Method::Fft) p.push_back({"fft_floor", format_number(o.method.fft_floor)});
  p.push_back({"stepper", stepper_name(o.integrator.stepper)});
  p.push_back({"rtol", format_number(o.integrator.rtol)});
  p.push_back({"atol", format_number(o.integrator.atol)});
  p.push_back({"convention", o.convention == Convention::Paper
                                 ? "paper (Eq. 3: dN/dt = sum K N N - 2 N sum K N; t = t_half / 2)"
                                 : "half (dc/dt = 1/2 sum K c c - c sum K c)"});
  p.push_back({"initial", o.initial});
  p.push_back({"volume", format_number(o.volume)});
  p.push_back({"bins_per_decade", std::to_string(o.bins_per_decade)});
  if (o.until_mean_mass) p.push_back({"until_mean_mass", format_number(*o.until_mean_mass)});
  return p;
}

// The two tables as TSV: N(m,t) blocks or the series on stdout, the series
// also in a file.
class TsvRows : public RunRows {
 public:
  TsvRows(const RunOptions& o, std::ostream& out) : o_(o), out_(out) {}
  bool wants_distribution() const override { return !o_.series; }
  bool wants_series() const override { return o_.series || !o_.series_file.empty(); }

  void begin(const Provenance& prov) override {
    if (!o_.series_file.empty()) {
      file_.open(o_.series_file);
      if (!file_) throw InputError("cannot write the series file '" + o_.series_file + "'");
    }
    const std::string tool = "coolgas-smoluchowski";
    if (o_.series) series_.emplace(out_, tool, prov, series_columns());
    else dist_.emplace(out_, tool, prov, distribution_columns());
    if (file_.is_open()) series_.emplace(file_, tool, prov, series_columns());
  }
  void distribution(const TableBlock& b) override {
    dist_->write(b);
    check_file();
  }
  void series(const std::vector<double>& row) override {
    series_->row(row);
    check_file();
  }
  void end(const std::string& line) override {
    out_ << "# " << line << "\n";
    if (!file_.is_open()) return;
    file_ << "# " << line << "\n";
    file_.close();
    check_file();
  }

 private:
  // A failed write to the series file (a full disk, /dev/full, a quota)
  // stops the run at once: exit code 5 naming the file, never exit 0 with
  // an empty or cut table. (errno is the failed write's: nothing else runs
  // between that write and this check.)
  void check_file() const {
    if (o_.series_file.empty() || !file_.fail()) return;
    throw WriteError("cannot write the series file '" + o_.series_file + "': " +
                     (errno ? std::strerror(errno) : "a write failed"));
  }
  const RunOptions& o_;
  std::ostream& out_;
  std::ofstream file_;
  std::optional<TsvWriter> dist_, series_;
};

// The rows of one checkpoint at time t_user (the options' convention).
void hand_over(RunRows& rows, const RunOptions& o, const Checkpoint& cp, double t_user, const MassGrid& g,
               const std::vector<double>& c) {
  const Moments mom = moments(g, c);
  if (cp.distribution && rows.wants_distribution()) {
    TableBlock b{"t = " + format_number(t_user), {}};
    for (const auto& p : binned_distribution(g, c, o.bins_per_decade))
      b.rows.push_back({t_user, p.m, p.dm, p.N, p.m / mom.mean(), p.N * mom.mean() * mom.mean()});
    rows.distribution(b);
  }
  if (cp.series && rows.wants_series()) {
    const double mmax = largest_mass(g, c, o.volume);
    rows.series({t_user, mom.M0, mom.M1, mom.M2, mom.mean(), mmax, mmax / (mom.M1 * o.volume)});
  }
}

// Finds the time at which the mean mass reaches `target` inside the last step
// [t_a, t_b] by regula falsi on restarts from the saved state at t_a.
void refine_crossing(Integrator& it, const MassGrid& g, double target, double t_a, std::vector<double> c_a) {
  double m_a = moments(g, c_a).mean(), t_b = it.time(), m_b = moments(g, it.state()).mean();
  for (int iter = 0; iter < 60; ++iter) {
    double t = t_a + (t_b - t_a) * (target - m_a) / (m_b - m_a);
    if (iter % 3 == 2 || !(t > t_a && t < t_b)) t = 0.5 * (t_a + t_b);  // keep the bracket shrinking
    it.reset(t_a, c_a);
    it.advance_to(t);
    const double m = moments(g, it.state()).mean();
    if (std::abs(m - target) <= 1e-10 * target || t_b - t_a <= 1e-14 * t_b) return;
    if (m < target) {
      t_a = t;
      m_a = m;
      c_a = it.state();
    } else {
      t_b = t;
      m_b = m;
    }
  }
}

class LeakWatch {
 public:
  LeakWatch(const RunOptions& o, double M1_0, std::ostream& warn) : o_(o), M1_0_(M1_0), warn_(warn) {}
  double fraction(const MassGrid& g, const std::vector<double>& c) const { return 1 - moments(g, c).M1 / M1_0_; }
  void check(double t_user, const MassGrid& g, const std::vector<double>& c) {
    const double leaked = fraction(g, c);
    if (warned_ || leaked <= o_.leak_tolerance) return;
    warned_ = true;
    warn_ << "coolgas-smoluchowski: warning: a fraction " << format_number(leaked)
          << " of the mass has grown past the cut-off M = " << o_.method.M << " by t = " << format_number(t_user)
          << " (tolerance " << format_number(o_.leak_tolerance) << "); rerun with --M "
          << needed_cutoff(g, c, leaked, o_.leak_tolerance) << " or more\n";
  }

 private:
  const RunOptions& o_;
  double M1_0_;
  std::ostream& warn_;
  bool warned_ = false;
};

// Between two steps, so every row written so far is whole; only the table's
// '# end' line is missing (data-schema/tsv-tables.md).
[[noreturn]] void stop_interrupted(double t_user) {
  throw Interrupted(interrupt_signal(), "at t = " + format_number(t_user) +
                                            "; the rows written so far are complete, the '# end' line is missing");
}

// A kernel whose rates overflow (e.g. separable:1e300,1,1) or whose
// solution blows up on this grid makes the state inf or nan; the table must
// not go on with rows of nan. Checked after each step (a sum over the grid,
// far cheaper than the step's right-hand side).
void check_finite(const MassGrid& g, const std::vector<double>& c, double t_user, const std::string& kernel) {
  const Moments m = moments(g, c);
  if (std::isfinite(m.M0) && std::isfinite(m.M1) && std::isfinite(m.M2)) return;
  throw InputError("kernel '" + kernel + "': the solution overflows at t = " + format_number(t_user) +
                   " (rows so far are complete; no '# end' line)");
}

}  // namespace

const std::vector<std::string>& distribution_columns() {
  static const std::vector<std::string> columns{"t", "m", "dm", "N", "x", "y"};
  return columns;
}

const std::vector<std::string>& series_columns() {
  static const std::vector<std::string> columns{"t", "M0", "M1", "M2", "M_avg", "M_max", "largest_fraction"};
  return columns;
}

RunSummary run(const RunOptions& o, std::ostream& out, std::ostream& warn) {
  TsvRows rows(o, out);
  return run(o, rows, warn);
}

RunSummary run(const RunOptions& o, RunRows& rows, std::ostream& warn) {
  validate(o);
  const Kernel kernel = parse_kernel(o.kernel);
  check_run_memory(o, kernel, usable_memory_bytes());
  // The start first: a table's mass above the cut-off is refused before the
  // grid and the transforms are made.
  const std::vector<double> by_mass =
      o.initial_by_mass.empty() ? initial_masses(o.initial, o.method.M) : std::vector<double>();
  auto rhs = make_rhs(kernel, o.method);
  const MassGrid& g = rhs->grid();
  auto c0 = on_grid(g, o.initial_by_mass.empty() ? by_mass : o.initial_by_mass);
  const double M1_0 = moments(g, c0).M1;
  if (!(M1_0 > 0)) throw InputError("initial distribution '" + o.initial + "' holds no clusters");
  Integrator it(*rhs, std::move(c0), o.integrator);

  const double f = time_factor(o.convention);
  double t_stop = 0;
  if (o.t_end) t_stop = *o.t_end * f;
  else if (o.until_mean_mass) t_stop = kUntilCap;
  else t_stop = *std::max_element(o.times.begin(), o.times.end()) * f;
  rows.begin(provenance(o, kernel, g));
  LeakWatch leak(o, M1_0, warn);
  bool reached = false;
  for (const auto& cp : schedule(o, rows.wants_series(), t_stop)) {
    while (it.time() < cp.t && !reached) {
      if (interrupted()) stop_interrupted(it.time() / f);
      const double t_a = it.time();
      const auto c_a = it.state();
      it.step(cp.t);
      check_finite(g, it.state(), it.time() / f, o.kernel);
      rows.after_step();
      if (o.until_mean_mass && moments(g, it.state()).mean() >= *o.until_mean_mass) {
        refine_crossing(it, g, *o.until_mean_mass, t_a, c_a);
        reached = true;
      }
    }
    const Checkpoint here = reached ? Checkpoint{it.time(), true, true} : cp;
    hand_over(rows, o, here, it.time() / f, g, it.state());
    leak.check(it.time() / f, g, it.state());
    if (reached) break;
  }
  if (o.until_mean_mass && !reached)
    warn << "coolgas-smoluchowski: warning: the mean mass did not reach " << format_number(*o.until_mean_mass)
         << " by t = " << format_number(it.time() / f) << "\n";
  RunSummary s{it.time() / f, moments(g, it.state()), leak.fraction(g, it.state()), it.steps(), it.evaluations()};
  rows.end("end: t = " + format_number(s.t) + ", leaked_mass_fraction = " + format_number(s.leaked_fraction) +
                ", steps = " + std::to_string(s.steps) + ", rhs_evaluations = " + std::to_string(s.evaluations));
  return s;
}

}  // namespace coolgas::smoluchowski
