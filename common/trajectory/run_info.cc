#include "common/trajectory/run_info.h"

#include <cmath>

#include "common/error.h"
#include "common/hdf5_file.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

[[noreturn]] void not_a_trajectory(const std::string& path, const std::string& what) {
  throw InputError(path + ": not a coolgas trajectory: missing " + what);
}

void require_attrs(hid_t group, const std::string& path, const std::vector<std::string>& names) {
  for (const auto& n : names)
    if (!h5::has_attr(group, n)) not_a_trajectory(path, "/parameters attribute '" + n + "'");
}

std::vector<double> read_doubles(hid_t file, const std::string& path, const std::string& dataset) {
  if (!h5::exists(file, dataset)) not_a_trajectory(path, "/" + dataset);
  h5::Handle d = h5::open_dataset(file, dataset);
  const auto dims = h5::shape(d.id());
  if (dims.size() != 1)
    throw InputError(path + ": /" + dataset + " has rank " + std::to_string(dims.size()) +
                     ", expected a scalar per row (rank 1)");
  return h5::read_all<double>(d.id());
}

}  // namespace

RunInfo read_run_info(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  if (!h5::exists(f.id(), "parameters")) not_a_trajectory(path, "/parameters");
  h5::Handle g = h5::open_group(f.id(), "parameters");
  require_attrs(g.id(), path, {"N", "L", "phi", "T0", "model", "r0", "delta", "seed", "scene", "program_version"});
  RunInfo info;
  info.path = path;
  RunParameters& p = info.params;
  p.N = h5::read_attr_int(g.id(), "N");
  p.L = h5::read_attr_double(g.id(), "L");
  p.phi = h5::read_attr_double(g.id(), "phi");
  p.T0 = h5::read_attr_double(g.id(), "T0");
  p.model = h5::read_attr_string(g.id(), "model");
  p.r0 = h5::read_attr_double(g.id(), "r0");
  p.delta = h5::read_attr_double(g.id(), "delta");
  p.seed = h5::read_attr_int(g.id(), "seed");
  p.scene_toml = h5::read_attr_string(g.id(), "scene");
  info.program_version = h5::read_attr_string(g.id(), "program_version");
  if (!(p.L > 0) || p.N <= 0)
    throw InputError(path + ": /parameters has N = " + std::to_string(p.N) + ", L = " + format_number(p.L) +
                     "; both must be positive");
  return info;
}

ObservableSeries read_observable(const std::string& path, const std::string& name) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const std::string element = "observables/" + name;
  if (!h5::exists(f.id(), element)) not_a_trajectory(path, "/" + element);
  ObservableSeries s{read_doubles(f.id(), path, element + "/time"), read_doubles(f.id(), path, element + "/value")};
  if (s.time.empty()) throw InputError(path + ": /" + element + " has no rows (the run recorded nothing)");
  if (s.time.size() != s.value.size())
    throw InputError(path + ": /" + element + " has " + std::to_string(s.time.size()) + " times but " +
                     std::to_string(s.value.size()) + " values; they must match");
  for (std::size_t i = 0; i < s.time.size(); ++i) {
    if (!std::isfinite(s.time[i]) || !std::isfinite(s.value[i]))
      throw InputError(path + ": /" + element + " row " + std::to_string(i) + " is not finite (time " +
                       format_number(s.time[i]) + ", value " + format_number(s.value[i]) + ")");
    if (i > 0 && s.time[i] < s.time[i - 1])
      throw InputError(path + ": /" + element + "/time decreases at row " + std::to_string(i) + " (" +
                       format_number(s.time[i - 1]) + " then " + format_number(s.time[i]) + ")");
  }
  return s;
}

std::optional<std::string> physics_difference(const RunParameters& a, const RunParameters& b) {
  auto num = [](const char* key, double x, double y) -> std::optional<std::string> {
    if (x == y) return std::nullopt;
    return std::string(key) + " = " + format_number(x) + " vs " + format_number(y);
  };
  if (a.model != b.model) return "model = " + a.model + " vs " + b.model;
  if (auto d = num("N", double(a.N), double(b.N))) return d;
  if (auto d = num("L", a.L, b.L)) return d;
  if (auto d = num("phi", a.phi, b.phi)) return d;
  if (auto d = num("T0", a.T0, b.T0)) return d;
  if (auto d = num("r0", a.r0, b.r0)) return d;
  return num("delta", a.delta, b.delta);
}

}  // namespace coolgas
