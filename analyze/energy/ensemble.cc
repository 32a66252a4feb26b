#include "analyze/energy/ensemble.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "analyze/energy/grid.h"
#include "common/error.h"
#include "common/geometry.h"
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

// A series' rows with t > 0: the t = 0 row has ln t = -inf.
ObservableSeries positive_part(const ObservableSeries& s) {
  const auto first = std::upper_bound(s.time.begin(), s.time.end(), 0.0) - s.time.begin();
  return {{s.time.begin() + first, s.time.end()}, {s.value.begin() + first, s.value.end()}};
}

EnergyRow average_row(double t, const std::vector<double>& E, const std::vector<double>& ratio) {
  const MeanErr e = mean_and_standard_error(E), r = mean_and_standard_error(ratio);
  return {t, e.mean, e.err, r.mean, r.err, static_cast<int>(E.size())};
}

// Every energy of a series is positive (log-log interpolation needs it).
void require_positive(const std::string& path, const ObservableSeries& s, const char* what) {
  for (std::size_t i = 0; i < s.value.size(); ++i)
    if (!(s.value[i] > 0))
      throw InputError(path + ": " + what + " " + format_number(s.value[i]) + " at t = " + format_number(s.time[i]) +
                       " is not positive; coolgas-energy needs E > 0 (it interpolates ln E against ln t)");
}

// A rough ensemble's temperatures from each run's energies at one time
// (E_tr the kinetic energy, E_rot the rotational, per particle).
TwoTemperatures temperatures_of(const std::vector<double>& E_tr, const std::vector<double>& E_rot, Geometry g) {
  std::vector<double> tr(E_tr.size()), rot(E_rot.size());
  for (std::size_t k = 0; k < tr.size(); ++k) {
    tr[k] = E_tr[k] / g.energy_per_temperature();
    rot[k] = 2.0 * E_rot[k] / g.rotational_axes();
  }
  const MeanErr a = mean_and_standard_error(tr), b = mean_and_standard_error(rot);
  return {a.mean, a.err, b.mean, b.err};
}

// A mixture's species temperatures from each run's energies at one time.
std::vector<std::pair<double, double>> species_temperatures_of(const std::vector<std::vector<double>>& E, Geometry g) {
  std::vector<std::pair<double, double>> out;
  for (const std::vector<double>& runs : E) {
    std::vector<double> T(runs.size());
    for (std::size_t k = 0; k < T.size(); ++k) T[k] = runs[k] / g.energy_per_temperature();
    const MeanErr m = mean_and_standard_error(T);
    out.emplace_back(m.mean, m.err);
  }
  return out;
}

// A mixture's species energies, one series per species, at the kinetic energy's times.
std::vector<ObservableSeries> species_series(const std::string& path, const EnergyRun& run) {
  const ObservableRows rows = read_observable_rows(path, layout::kSpeciesKineticEnergy);
  if (rows.time != run.energy.time || rows.per_row != run.info.params.species_fraction.size())
    throw InputError(path + ": /observables/species_kinetic_energy is not one value per species at the kinetic "
                            "energy's times");
  std::vector<ObservableSeries> out(rows.per_row);
  for (std::size_t s = 0; s < rows.per_row; ++s) {
    out[s].time = rows.time;
    for (std::size_t r = 0; r < rows.time.size(); ++r) out[s].value.push_back(rows.value[r * rows.per_row + s]);
    require_positive(path, out[s], ("species " + std::to_string(s) + " kinetic energy").c_str());
  }
  return out;
}

}  // namespace

EnergyRun load_energy_run(const std::string& path) {
  EnergyRun run{read_run_info(path), read_observable(path, layout::kKineticEnergy), std::nullopt, {}};
  require_positive(path, run.energy, "kinetic energy");
  if (is_rough(run.info.params.collision)) {
    run.rotational = read_observable(path, layout::kRotationalEnergy);
    require_positive(path, *run.rotational, "rotational energy");
    if (run.rotational->time != run.energy.time)
      throw InputError(path + ": /observables/rotational_energy is not recorded at the kinetic energy's times");
  }
  if (has_particle_species(run.info.params)) run.species = species_series(path, run);
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
  std::vector<double> E(runs.size()), ratio(runs.size()), rot(runs.size());
  const bool rough = runs[0].rotational.has_value();  // the runs share their physics
  const std::size_t species = runs[0].species.size();
  std::vector<std::vector<double>> E_s(species, std::vector<double>(runs.size()));  // [species][run]
  const Geometry g(runs[0].info.dimension);
  if (all_have_zero) {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      E[k] = runs[k].energy.value[0], ratio[k] = 1;
      if (rough) rot[k] = runs[k].rotational->value[0];
      for (std::size_t s = 0; s < species; ++s) E_s[s][k] = runs[k].species[s].value[0];
    }
    rows.push_back(average_row(0, E, ratio));
    if (rough) rows.back().temperatures = temperatures_of(E, rot, g);
    rows.back().species_temperatures = species_temperatures_of(E_s, g);
  }
  std::vector<ObservableSeries> positive, positive_rot;
  std::vector<std::vector<ObservableSeries>> positive_species;  // [run][species]
  for (const auto& r : runs) {
    positive.push_back(positive_part(r.energy));
    if (rough) positive_rot.push_back(positive_part(*r.rotational));
    positive_species.emplace_back();
    for (const ObservableSeries& s : r.species) positive_species.back().push_back(positive_part(s));
  }
  for (double t : log_time_grid(t_lo, t_hi, per_decade)) {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      E[k] = interpolate_loglog(positive[k].time, positive[k].value, t);
      ratio[k] = E[k] / runs[k].energy.value[0];
      if (rough) rot[k] = interpolate_loglog(positive_rot[k].time, positive_rot[k].value, t);
      for (std::size_t s = 0; s < species; ++s)
        E_s[s][k] = interpolate_loglog(positive_species[k][s].time, positive_species[k][s].value, t);
    }
    rows.push_back(average_row(t, E, ratio));
    if (rough) rows.back().temperatures = temperatures_of(E, rot, g);
    rows.back().species_temperatures = species_temperatures_of(E_s, g);
  }
  return rows;
}

}  // namespace coolgas
