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
#include "analyze/smoluchowski/method.h"
#include "analyze/smoluchowski/observables.h"

namespace coolgas::smoluchowski {

enum class Convention { HalfGain, Paper };

Convention parse_convention(const std::string& name);  // "half" or "paper"

struct RunOptions {
  std::string kernel = "ballistic";
  MethodOptions method;
  IntegratorOptions integrator;
  Convention convention = Convention::HalfGain;
  std::string initial = "mono";
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

struct RunSummary {
  double t = 0;                 // final time (the options' convention)
  Moments final_moments;
  double leaked_fraction = 0;   // 1 − M1(t)/M1(0)
  long steps = 0, evaluations = 0;
};

// Runs and writes the tables; warnings (mass leak, target not reached) go to
// `warn` as single lines.
RunSummary run(const RunOptions& o, std::ostream& out, std::ostream& warn);

}  // namespace coolgas::smoluchowski
