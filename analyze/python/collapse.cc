// The energy collapse, wrapped: finite-size scaling of several E(t) curves
// (analyze/collapse/table.h), as coolgas-collapse computes it from its tables.
#include "analyze/collapse/table.h"
#include "analyze/python/arrays.h"

namespace coolgas::python {
namespace {

// Each curve: a dict {"columns", "rows" (2-D), "L", "source"}, the table
// coolgas-collapse would read (its "# L:" line from "L").
std::vector<Table> tables_of(const py::list& curves) {
  std::vector<Table> tables;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const auto d = curves[i].cast<py::dict>();
    const auto source = d["source"].cast<std::string>();
    const double L = d["L"].cast<double>();
    if (!(L > 0) || !std::isfinite(L))
      throw InputError(source + ": L = " + format_number(L) + " is not a box side (a number > 0)");
    tables.push_back(table_of(d["columns"].cast<std::vector<std::string>>(), real_numbers(d["rows"], source + ": rows"),
                              source, {{"L", format_number(L)}}));
  }
  return tables;
}

py::dict collapse(const py::list& curves, double theta, double z, bool optimize, int bootstrap, std::uint64_t seed,
                  double min_overlap, const std::optional<std::string>& t_window,
                  const std::optional<std::string>& eta_window, const std::string& weights, bool summary,
                  const std::string& t_column, const std::string& e_column, const std::optional<double>& z_theta) {
  if (weights != "none" && weights != "seeds")
    throw InputError("weights = '" + shown(weights) + "' is not a weighting; allowed: none, seeds");
  if (bootstrap < 0) throw InputError("bootstrap must be >= 0 replicas, got " + std::to_string(bootstrap));
  if (z_theta && !optimize) throw InputError("z_theta holds z theta fixed while optimising: it needs optimize=True");
  CollapseOptions o;
  o.columns.t = t_column;
  o.columns.E = e_column;
  o.theta = theta;
  o.z = z;
  o.optimize = optimize;
  o.search.bootstrap = bootstrap;
  o.search.seed = seed;
  o.search.min_overlap_decades = min_overlap;
  if (t_window) o.t_window = parse_window(*t_window, "t_window");
  o.auto_window = optimize && !t_window;
  if (eta_window) o.eta_window = parse_window(*eta_window, "eta_window");
  o.seed_weights = weights == "seeds";
  o.summary = summary;
  o.z_theta = z_theta;
  const CollapseResult r = collapse_tables(tables_of(curves), o);
  std::vector<std::vector<double>> rows;
  std::vector<std::int32_t> block;
  for (std::size_t b = 0; b < r.blocks.size(); ++b)
    for (const auto& row : r.blocks[b].rows) {
      rows.push_back(row);
      block.push_back(std::int32_t(b));
    }
  py::dict d = table_dict(r.columns, rows);
  d["block"] = to_numpy(std::move(block), {py::ssize_t(rows.size())});
  d["provenance"] = r.provenance;
  d["theta"] = r.theta;
  d["z"] = r.z;
  d["quality"] = r.quality;
  const auto number_or_none = [](bool has, double v) { return has ? py::object(py::float_(v)) : py::object(py::none()); };
  d["theta_err"] = number_or_none(bool(r.fit), r.fit ? r.fit->theta_err : 0);
  d["z_err"] = number_or_none(bool(r.fit), r.fit ? r.fit->z_err : 0);
  d["z_theta_err"] = number_or_none(r.fit && !z_theta, r.fit ? r.fit->z_theta_err : 0);  // the free fit's product
  d["eta"] = number_or_none(bool(r.eta), r.eta ? r.eta->theta : 0);
  d["eta_err"] = number_or_none(bool(r.eta), r.eta ? r.eta->theta_err : 0);
  return d;
}

}  // namespace

void bind_collapse(py::module_& m) {
  const CollapseOptions d;  // the tool's defaults
  m.def("collapse", &collapse, py::arg("curves"), py::arg("theta") = d.theta, py::arg("z") = d.z,
        py::arg("optimize") = false, py::arg("bootstrap") = d.search.bootstrap, py::arg("seed") = d.search.seed,
        py::arg("min_overlap") = d.search.min_overlap_decades, py::arg("t_window") = py::none(),
        py::arg("eta_window") = py::none(), py::arg("weights") = "none", py::arg("summary") = false,
        py::arg("t_column") = d.columns.t, py::arg("e_column") = d.columns.E,
        py::arg("z_theta") = py::none());
}

}  // namespace coolgas::python
