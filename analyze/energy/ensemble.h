// E(t) of one run, or the mean over an ensemble of runs that differ only in
// their seed, on a common log-spaced time grid (coolgas-energy).
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/trajectory/run_info.h"

namespace coolgas {

// One trajectory's parameters and kinetic energy per particle.
struct EnergyRun {
  RunInfo info;
  ObservableSeries energy;  // /observables/kinetic_energy
  std::optional<ObservableSeries> rotational;  // /observables/rotational_energy: rough particles only
  std::vector<ObservableSeries> species;       // /observables/species_kinetic_energy by species: mixtures only
};

// A rough run's two temperatures per axis, T_tr = 2 E_tr/d and T_rot = 2 E_rot/d_r:
// the mean over runs and its standard error.
struct TwoTemperatures {
  double T_tr = 0, T_tr_err = 0, T_rot = 0, T_rot_err = 0;
};

// One row of the coolgas-energy table (data-schema/tsv-tables.md).
struct EnergyRow {
  double t = 0;
  double E = 0, E_err = 0;                  // mean over runs and its standard error
  double E_over_E0 = 0, E_over_E0_err = 0;  // mean of each run's E(t)/E(first row)
  int runs = 0;
  std::optional<TwoTemperatures> temperatures;  // rough runs only
  // A mixture's temperature per axis of each species, T_s = 2 E_s/d: mean over runs and its standard error.
  std::vector<std::pair<double, double>> species_temperatures;
};

// Reads a trajectory; rejects non-positive energies (log-log interpolation needs E > 0).
EnergyRun load_energy_run(const std::string& path);

// InputError naming both files and the first differing parameter unless every
// run has the same physics (physics_difference in common/trajectory/run_parameters.h: every
// parameter of role kPhysics, the model's own included).
void require_same_physics(const std::vector<EnergyRun>& runs);

// The ensemble table: a t = 0 row first if every run has one, then the grid
// log_time_grid(overlap of the runs' positive times, per_decade). Standard
// errors are s/sqrt(n) with the sample deviation s; 0 for a single run.
std::vector<EnergyRow> ensemble_energy(const std::vector<EnergyRun>& runs, int per_decade);

}  // namespace coolgas
