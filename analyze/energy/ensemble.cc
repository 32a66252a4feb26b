#include "analyze/energy/ensemble.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "analyze/energy/grid.h"
#include "common/error.h"
#include "common/trajectory/layout.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

struct MeanErr {
  double mean = 0, err = 0;
};

MeanErr mean_and_standard_error(const std::vector<double>& x) {
  const double n = double(x.size());
  double sum = 0;
  for (double v : x) sum += v;
  MeanErr r{sum / n, 0};
  if (x.size() < 2) return r;
  double ss = 0;
  for (double v : x) ss += (v - r.mean) * (v - r.mean);
  r.err = std::sqrt(ss / (n - 1) / n);
  return r;
}

// First recorded time > 0 (the t = 0 row cannot enter a log-log interpolation).
double first_positive_time(const EnergyRun& run) {
  for (double t : run.energy.time)
    if (t > 0) return t;
  throw InputError(run.info.path + ": /observables/kinetic_energy has no row with t > 0 (the run did not advance)");
}

// Each run's rows with t > 0: the t = 0 row has ln t = -inf.
std::vector<ObservableSeries> positive_times(const std::vector<EnergyRun>& runs) {
  std::vector<ObservableSeries> out;
  for (const auto& r : runs) {
    const auto& s = r.energy;
    const auto first = std::upper_bound(s.time.begin(), s.time.end(), 0.0) - s.time.begin();
    out.push_back({{s.time.begin() + first, s.time.end()}, {s.value.begin() + first, s.value.end()}});
  }
  return out;
}

EnergyRow average_row(double t, const std::vector<double>& E, const std::vector<double>& ratio) {
  const MeanErr e = mean_and_standard_error(E), r = mean_and_standard_error(ratio);
  return {t, e.mean, e.err, r.mean, r.err, static_cast<int>(E.size())};
}

}  // namespace

EnergyRun load_energy_run(const std::string& path) {
  EnergyRun run{read_run_info(path), read_observable(path, layout::kKineticEnergy)};
  const auto& s = run.energy;
  for (std::size_t i = 0; i < s.value.size(); ++i)
    if (!(s.value[i] > 0))
      throw InputError(path + ": kinetic energy " + format_number(s.value[i]) + " at t = " + format_number(s.time[i]) +
                       " is not positive; coolgas-energy needs E > 0 (it interpolates ln E against ln t)");
  return run;
}

void require_same_physics(const std::vector<EnergyRun>& runs) {
  for (std::size_t i = 1; i < runs.size(); ++i) {
    // The dimension is the box's, not a /parameters field: compared first.
    const int d0 = runs[0].info.dimension, d = runs[i].info.dimension;
    const std::optional<std::string> diff =
        d0 != d ? "dimension = " + std::to_string(d0) + " vs " + std::to_string(d)
                : physics_difference(runs[0].info.params, runs[i].info.params);
    if (diff)
      throw InputError("runs differ in their parameters, cannot average them: " + *diff + " (" + runs[0].info.path +
                       " vs " + runs[i].info.path + "); only the seed may differ");
  }
}

std::vector<EnergyRow> ensemble_energy(const std::vector<EnergyRun>& runs, int per_decade) {
  if (runs.empty()) throw InputError("no runs given");
  double t_lo = 0, t_hi = std::numeric_limits<double>::infinity();
  for (const auto& r : runs) {
    t_lo = std::max(t_lo, first_positive_time(r));
    t_hi = std::min(t_hi, r.energy.time.back());
  }
  if (t_lo > t_hi)
    throw InputError("the runs' time ranges do not overlap (latest start " + format_number(t_lo) +
                     " > earliest end " + format_number(t_hi) + ")");
  std::vector<EnergyRow> rows;
  const bool all_have_zero = std::all_of(runs.begin(), runs.end(), [](const EnergyRun& r) { return r.energy.time[0] == 0; });
  std::vector<double> E(runs.size()), ratio(runs.size());
  if (all_have_zero) {
    for (std::size_t k = 0; k < runs.size(); ++k) E[k] = runs[k].energy.value[0], ratio[k] = 1;
    rows.push_back(average_row(0, E, ratio));
  }
  const std::vector<ObservableSeries> positive = positive_times(runs);
  for (double t : log_time_grid(t_lo, t_hi, per_decade)) {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      E[k] = interpolate_loglog(positive[k].time, positive[k].value, t);
      ratio[k] = E[k] / runs[k].energy.value[0];
    }
    rows.push_back(average_row(t, E, ratio));
  }
  return rows;
}

}  // namespace coolgas
