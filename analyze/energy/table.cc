#include "analyze/energy/table.h"

#include <ostream>

#include "analyze/energy/ensemble.h"
#include "common/dimension_line.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

// The physics fields (N, L, ..., the model's own; run_parameters.h) go into
// the provenance: coolgas-collapse reads L from it.
Provenance energy_provenance(const std::vector<EnergyRun>& runs, int per_decade) {
  Provenance p;
  std::string seeds;
  for (const auto& r : runs) {
    p.emplace_back("input", r.info.path);
    if (!seeds.empty()) seeds += ' ';
    seeds += std::to_string(r.info.params.seed);
  }
  p.emplace_back("runs", std::to_string(runs.size()));
  p.emplace_back("seeds", seeds);
  for (auto& entry : physics_provenance(runs[0].info.params)) p.push_back(std::move(entry));
  add_dimension_line(p, runs[0].info.dimension);
  p.emplace_back("simulator_version", runs[0].info.params.program_version);
  p.emplace_back("per_decade", std::to_string(per_decade));
  return p;
}

}  // namespace

void write_energy_table(const EnergyOptions& options, std::ostream& out) {
  if (options.inputs.empty()) throw InputError("no trajectory files given (usage: coolgas-energy RUN.h5...)");
  // Beyond 1e4 points per decade (steps of 0.02 %) the rows are interpolation only, and the table grows without bound.
  if (options.per_decade < 1 || options.per_decade > 10000)
    throw InputError("--per-decade " + std::to_string(options.per_decade) + " is not allowed; it must be in [1, 10000]");
  // Hundreds of seeds' files (on a network file system) are minutes of
  // reading: a signal stops it between two files. (The average itself is
  // at most 10^4 rows per decade, seconds.)
  std::vector<EnergyRun> runs;
  for (std::size_t i = 0; i < options.inputs.size(); ++i) {
    throw_if_interrupted(i, options.inputs.size(), "runs");
    runs.push_back(load_energy_run(options.inputs[i]));
  }
  require_same_physics(runs);
  // Everything is computed before the first line is written: an error leaves no half table.
  const auto rows = ensemble_energy(runs, options.per_decade);
  // Rough particles add both temperatures per axis (a smooth run's table is as before).
  std::vector<std::string> columns = {"t", "E", "E_err", "E_over_E0", "E_over_E0_err", "runs"};
  if (runs[0].rotational) columns.insert(columns.end(), {"T_tr", "T_tr_err", "T_rot", "T_rot_err"});
  // A mixture adds each species' temperature per axis, by its index in the file (0: the first [[species]]).
  for (std::size_t s = 0; s < runs[0].species.size(); ++s)
    columns.insert(columns.end(), {"T_species_" + std::to_string(s), "T_species_" + std::to_string(s) + "_err"});
  TsvWriter w(out, "coolgas-energy", energy_provenance(runs, options.per_decade), columns);
  for (const auto& r : rows) {
    std::vector<double> row = {r.t, r.E, r.E_err, r.E_over_E0, r.E_over_E0_err, double(r.runs)};
    if (const auto& T = r.temperatures) row.insert(row.end(), {T->T_tr, T->T_tr_err, T->T_rot, T->T_rot_err});
    for (const auto& [T, err] : r.species_temperatures) row.insert(row.end(), {T, err});
    w.row(row);
  }
}

}  // namespace coolgas
