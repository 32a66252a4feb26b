#include "common/trajectory/run_info.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/hdf5_file.h"
#include "common/trajectory/layout.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

[[noreturn]] void not_a_trajectory(const std::string& path, const std::string& what) {
  throw InputError(path + ": not a coolgas trajectory: missing " + what);
}

std::vector<double> read_doubles(hid_t file, const std::string& path, const std::string& dataset) {
  if (!h5::exists(file, dataset)) not_a_trajectory(path, dataset);
  h5::Handle d = h5::open_dataset(file, dataset);
  const auto dims = h5::shape(d.id());
  if (dims.size() != 1)
    throw InputError(path + ": " + dataset + " has rank " + std::to_string(dims.size()) +
                     ", expected a scalar per row (rank 1)");
  return h5::read_all<double>(d.id());
}

}  // namespace

RunInfo read_run_info(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  RunInfo info{path, read_file_parameters(f.id(), path)};
  const RunParameters& p = info.params;
  if (!(p.L > 0) || p.N <= 0)
    throw InputError(path + ": /parameters has N = " + std::to_string(p.N) + ", L = " + format_number(p.L) +
                     "; both must be positive");
  return info;
}

// Rows of `time` up to the last complete dump: later ones may still be being written.
std::size_t complete_rows(hid_t file, const std::vector<double>& time) {
  const auto last = layout::last_dump_time(file);
  if (!last) return time.size();
  return std::size_t(std::upper_bound(time.begin(), time.end(), *last) - time.begin());
}

ObservableSeries read_observable(const std::string& path, std::string_view name) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const std::string element(name);
  if (!h5::exists(f.id(), element)) not_a_trajectory(path, element);
  ObservableSeries s{read_doubles(f.id(), path, layout::time_of(element)),
                     read_doubles(f.id(), path, layout::value_of(element))};
  const std::size_t rows = complete_rows(f.id(), s.time);
  if (s.value.size() < rows)
    throw InputError(path + ": " + element + " has " + std::to_string(rows) + " times but " +
                     std::to_string(s.value.size()) + " values; they must match");
  s.time.resize(rows);
  s.value.resize(rows);
  if (s.time.empty()) throw InputError(path + ": " + element + " has no rows (the run recorded nothing)");
  for (std::size_t i = 0; i < s.time.size(); ++i) {
    if (!std::isfinite(s.time[i]) || !std::isfinite(s.value[i]))
      throw InputError(path + ": " + element + " row " + std::to_string(i) + " is not finite (time " +
                       format_number(s.time[i]) + ", value " + format_number(s.value[i]) + ")");
    if (i > 0 && s.time[i] < s.time[i - 1])
      throw InputError(path + ": " + element + "/time decreases at row " + std::to_string(i) + " (" +
                       format_number(s.time[i - 1]) + " then " + format_number(s.time[i]) + ")");
  }
  return s;
}

}  // namespace coolgas
