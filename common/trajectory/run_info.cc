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

// The numbers of a dataset of one (rank 1) or, when `vectors`, several
// (rank 2) numbers per row; the row length into *per_row.
std::vector<double> read_doubles(hid_t file, const std::string& path, const std::string& dataset, bool vectors = false,
                                 std::size_t* per_row = nullptr, bool* is_vector = nullptr) {
  if (!h5::exists(file, dataset)) not_a_trajectory(path, dataset);
  h5::Handle d = h5::open_dataset(file, dataset);
  const auto dims = h5::shape(d.id());
  if (dims.size() != 1 && !(vectors && dims.size() == 2))
    throw InputError(path + ": " + dataset + " has rank " + std::to_string(dims.size()) +
                     (vectors ? ", expected a scalar or a vector per row (rank 1 or 2)" : ", expected a scalar per row (rank 1)"));
  if (per_row) *per_row = dims.size() == 2 ? std::size_t(dims[1]) : 1;
  if (is_vector) *is_vector = dims.size() == 2;
  return h5::read_all<double>(d.id());
}

}  // namespace

RunInfo read_run_info(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  RunInfo info{path, read_file_parameters(f.id(), path), layout::dimension_of(f.id())};
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

ObservableRows read_observable_rows(const std::string& path, std::string_view name) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const std::string element(name);
  if (!h5::exists(f.id(), element)) not_a_trajectory(path, element);
  ObservableRows s;
  s.time = read_doubles(f.id(), path, layout::time_of(element));
  s.value = read_doubles(f.id(), path, layout::value_of(element), true, &s.per_row, &s.vectors);
  const std::size_t k = s.per_row;
  const std::size_t rows = complete_rows(f.id(), s.time);
  if (k == 0 || s.value.size() / k < rows)
    throw InputError(path + ": " + element + " has " + std::to_string(rows) + " times but " +
                     std::to_string(k ? s.value.size() / k : 0) + " values; they must match");
  s.time.resize(rows);
  s.value.resize(rows * k);
  if (s.time.empty()) throw InputError(path + ": " + element + " has no rows (the run recorded nothing)");
  for (std::size_t i = 0; i < s.time.size(); ++i) {
    for (std::size_t c = 0; c < k; ++c)
      if (!std::isfinite(s.time[i]) || !std::isfinite(s.value[i * k + c]))
        throw InputError(path + ": " + element + " row " + std::to_string(i) + " is not finite (time " +
                         format_number(s.time[i]) + ", value " + format_number(s.value[i * k + c]) + ")");
    if (i > 0 && s.time[i] < s.time[i - 1])
      throw InputError(path + ": " + element + "/time decreases at row " + std::to_string(i) + " (" +
                       format_number(s.time[i - 1]) + " then " + format_number(s.time[i]) + ")");
  }
  return s;
}

ObservableSeries read_observable(const std::string& path, std::string_view name) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const std::string element(name);
  if (!h5::exists(f.id(), element)) not_a_trajectory(path, element);
  // The errors in their former order: a missing time, then a value that is not a scalar per row.
  read_doubles(f.id(), path, layout::time_of(element));
  read_doubles(f.id(), path, layout::value_of(element));
  ObservableRows r = read_observable_rows(path, name);
  return {std::move(r.time), std::move(r.value)};
}

std::vector<std::string> observable_names(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const std::string group(layout::kObservables);
  std::vector<std::string> names;
  if (!h5::exists(f.id(), group)) return names;
  h5::Handle g = h5::open_group(f.id(), group);
  H5G_info_t info;
  if (H5Gget_info(g.id(), &info) < 0) return names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256] = {};
    if (H5Lget_name_by_idx(g.id(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT) > 0)
      names.emplace_back(name);
  }
  return names;
}

}  // namespace coolgas
