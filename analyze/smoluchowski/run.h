// The coolgas-smoluchowski run: integrate from the initial distribution and
// write N(m,t) blocks and/or the series of moments as TSV tables (shapes in
// data-schema/tsv-tables.md, "Shared table shapes").
//
// Time convention: by default the ½-gain convention,
//   dc_k/dt = ½ Σ_{i+j=k} K(i,j) c_i c_j − c_k Σ_j K(k,j) c_j,
// with c_1(0) = 1 and K exactly as the kernel string gives it. The paper's
// Eq. (3) is the same equation without the ½ and with a 2 on the loss term,
// i.e. twice as fast: t_paper = t_half / 2. Convention::Paper reads and writes
// all times (options and the t column) in the paper's units.
#pragma once
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "analyze/smoluchowski/integrator.h"
#include "analyze/smoluchowski/kernel.h"
#include "analyze/smoluchowski/method.h"
#include "analyze/smoluchowski/observables.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

enum class Convention { HalfGain, Paper };

Convention parse_convention(const std::string& name);  // "half" or "paper"

struct RunOptions {
  std::string kernel = "ballistic";
  MethodOptions method;
  IntegratorOptions integrator;
  Convention convention = Convention::HalfGain;
  std::string initial = "mono";            // "mono" or a table's path (initial.h)
  std::vector<double> initial_by_mass;    // when not empty: c_m(0) by mass (initial.h), `initial` only names it
  std::vector<double> times;              // N(m,t) blocks at these times (and at the end)
  std::optional<double> t_end;            // stop here
  std::optional<double> until_mean_mass;  // or stop when M_avg reaches this
  bool series = false;                    // stdout gets the series instead of N(m,t)
  std::string series_file;                // also write the series to this path
  double series_t_min = 0.01;             // series rows at 0 and t_min 10^(k/per_decade)
  int series_per_decade = 10;
  int bins_per_decade = 10;
  double volume = 1e6;                    // system volume V for M_max (c_1(0) = 1: V particles)
  double leak_tolerance = 1e-6;           // warn when this fraction of the mass has leaked past M
};

// InputError (one line) for anything that cannot run: negative or non-finite
// times, nothing to do, bad knobs.
void validate(const RunOptions& o);

// The bytes a run of `o` needs at its peak: the method's (method_bytes),
// the stepper's (integrator_bytes), the run's copies of the state and the
// initial distribution by mass.
double run_bytes(const RunOptions& o, const Kernel& kernel);
// InputError naming --M, what the run would need, the memory available and
// the largest --M that fits, when run_bytes exceeds `memory_bytes` (the
// tool's: usable_memory_bytes(), common/memory.h). run() calls it before it
// allocates anything.
void check_run_memory(const RunOptions& o, const Kernel& kernel, double memory_bytes);

struct RunSummary {
  double t = 0;                 // final time (the options' convention)
  Moments final_moments;
  double leaked_fraction = 0;   // 1 − M1(t)/M1(0)
  long steps = 0, evaluations = 0;
};

// What a run produces, as it goes: the tool writes it as TSV tables, the
// Python module (analyze/python/) collects it.
class RunRows {
 public:
  virtual ~RunRows() = default;
  virtual bool wants_distribution() const = 0;
  virtual bool wants_series() const = 0;  // adds the series' times to the steps' limits
  // Once, before the first step (what the tables' headers say).
  virtual void begin(const Provenance& provenance) = 0;
  virtual void distribution(const TableBlock& block) = 0;  // N(m,t) at one time
  virtual void series(const std::vector<double>& row) = 0;
  virtual void end(const std::string& line) = 0;  // "end: t = ..., leaked_mass_fraction = ..."
  // After every step: a caller that cannot take SIGINT through the tool's
  // flag (Python) lets Ctrl-C through here.
  virtual void after_step() {}
};

const std::vector<std::string>& distribution_columns();  // t m dm N x y
const std::vector<std::string>& series_columns();        // t M0 M1 M2 M_avg M_max largest_fraction

// Runs, handing the rows to `rows`; warnings (mass leak, target not
// reached) go to `warn` as single lines.
RunSummary run(const RunOptions& o, RunRows& rows, std::ostream& warn);
// Runs and writes the tables: N(m,t) or, with o.series, the series on
// `out`, the series also to o.series_file when given.
RunSummary run(const RunOptions& o, std::ostream& out, std::ostream& warn);

}  // namespace coolgas::smoluchowski
