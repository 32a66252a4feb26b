// Reading a coolgas trajectory's identity and observables (data-schema/h5md-profile.md)
// for the analysis tools: the /parameters attributes and one /observables element.
//
// Every problem with a file is an InputError naming the file and what is
// missing or wrong, e.g. "run.h5: not a coolgas trajectory: missing
// /observables/kinetic_energy".
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "common/trajectory/h5md_writer.h"

namespace coolgas {

// The run's inputs as stored in /parameters, and where they came from.
struct RunInfo {
  std::string path;
  RunParameters params;         // N, L, phi, T0, model, r0, delta, seed, scene
  std::string program_version;  // of the coolgas-simulate that wrote the file
};

// One H5MD element of /observables: value[i] was recorded at time[i].
struct ObservableSeries {
  std::vector<double> time;
  std::vector<double> value;
};

RunInfo read_run_info(const std::string& path);

// Reads /observables/<name> (a scalar per row). Rejects an empty element,
// time and value of different lengths, decreasing times and non-finite numbers.
ObservableSeries read_observable(const std::string& path, const std::string& name);

// "Equal parameters" for an ensemble: every /parameters attribute that
// defines the physics (N, L, phi, T0, model, r0, delta) is equal; seed, scene
// text and program_version may differ. The scene text is not compared because
// it differs in the seed line and in output settings (t_end, dump grids) that
// do not change the physics; the attributes hold everything that does.
// Returns a description of the first difference, e.g. "L = 32 vs 48", or nothing.
std::optional<std::string> physics_difference(const RunParameters& a, const RunParameters& b);

}  // namespace coolgas
