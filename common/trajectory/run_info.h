// Reading a coolgas trajectory's identity and observables (data-schema/h5md-profile.md)
// for the analysis tools: the /parameters attributes and one /observables element.
//
// Every problem with a file is an InputError naming the file and what is
// missing or wrong, e.g. "run.h5: not a coolgas trajectory: missing
// /observables/kinetic_energy".
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/trajectory/run_parameters.h"

namespace coolgas {

// The run's inputs as stored in /parameters, and where they came from.
struct RunInfo {
  std::string path;
  RunParameters params;  // every field of run_parameters.h that the file's model has
  int dimension = 3;     // box/dimension: 3, 2 for disks, 1 for rods
};

// One H5MD element of /observables: value[i] was recorded at time[i].
struct ObservableSeries {
  std::vector<double> time;
  std::vector<double> value;
};

// An element with `per_row` numbers in each row (total_momentum: 3), row-major.
struct ObservableRows {
  std::vector<double> time;
  std::vector<double> value;
  std::size_t per_row = 1;
  bool vectors = false;  // rank 2: a vector per row, even of one number (a 1D run's total_momentum)
};

RunInfo read_run_info(const std::string& path);

// The names of the elements under /observables (e.g. "kinetic_energy"), in
// the file's name order; empty when the file has no /observables.
std::vector<std::string> observable_names(const std::string& path);

// Reads an observable element (layout.h, e.g. layout::kKineticEnergy; a
// scalar per row) up to the last complete dump (all rows if the file has no
// dump). Rejects an empty element, fewer values than times, decreasing
// times and non-finite numbers.
ObservableSeries read_observable(const std::string& path, std::string_view element);
// The same for an element of a scalar or a vector per row, with the same checks.
ObservableRows read_observable_rows(const std::string& path, std::string_view element);

// The ensemble check ("the same physics") is physics_difference() of
// run_parameters.h: every field of role kPhysics is compared.

}  // namespace coolgas
