// The Smoluchowski solver, wrapped: a coolgas-smoluchowski run
// (analyze/smoluchowski/run.h) whose rows are collected instead of written.
#include <sstream>

#include "analyze/python/arrays.h"
#include "analyze/smoluchowski/initial.h"
#include "analyze/smoluchowski/run.h"

namespace coolgas::python {
namespace {

namespace sm = coolgas::smoluchowski;

// The rows of the tables asked for, kept; Ctrl-C raises KeyboardInterrupt
// between two steps (the run's own flag is the tools' signal handler's).
class CollectedRows : public sm::RunRows {
 public:
  CollectedRows(bool distribution, bool series) : want_distribution_(distribution), want_series_(series) {}
  bool wants_distribution() const override { return want_distribution_; }
  bool wants_series() const override { return want_series_; }
  void begin(const Provenance& provenance) override { provenance_ = provenance; }
  void distribution(const TableBlock& b) override {
    comments_.push_back(b.comment);
    for (const auto& r : b.rows) {
      distribution_.push_back(r);
      block_.push_back(std::int32_t(comments_.size() - 1));
    }
  }
  void series(const std::vector<double>& row) override { series_.push_back(row); }
  void end(const std::string& line) override { end_ = line; }
  void after_step() override {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }

  py::dict result() {
    py::dict d;
    d["provenance"] = provenance_;
    d["end"] = end_;
    if (want_distribution_) {
      py::dict t = table_dict(sm::distribution_columns(), distribution_);
      t["block"] = to_numpy(std::move(block_), {py::ssize_t(distribution_.size())});
      t["comments"] = comments_;
      d["distribution"] = t;
    }
    if (want_series_) d["series"] = table_dict(sm::series_columns(), series_);
    return d;
  }

 private:
  bool want_distribution_, want_series_;
  Provenance provenance_;
  std::vector<std::vector<double>> distribution_, series_;
  std::vector<std::int32_t> block_;
  std::vector<std::string> comments_;
  std::string end_;
};

// initial: "mono", a table's path, or a dict {"columns", "rows"} (m, N [, dm]).
void set_initial(sm::RunOptions& o, const py::object& initial) {
  if (py::isinstance<py::str>(initial)) {
    o.initial = initial.cast<std::string>();
    return;
  }
  const auto d = initial.cast<py::dict>();
  o.initial = d["source"].cast<std::string>();
  o.initial_by_mass = sm::initial_masses(table_of(d["columns"].cast<std::vector<std::string>>(),
                                                  real_numbers(d["rows"], o.initial + ": rows"), o.initial),
                                         o.method.M);
}

py::dict run(const std::string& kernel, const std::string& method, std::int64_t M, double grid_ratio, double fft_floor,
             double rtol, double atol, const std::string& stepper, const std::string& convention,
             const py::object& initial, const std::vector<double>& times, const std::optional<double>& t_end,
             const std::optional<double>& until_mean_mass, const std::string& table, double series_t_min,
             int per_decade, int bins_per_decade, double volume, double leak_tolerance) {
  if (table != "distribution" && table != "series" && table != "both")
    throw InputError("table = '" + shown(table) + "' is not a Smoluchowski table; allowed: distribution, series, both");
  sm::RunOptions o;
  o.kernel = kernel;
  o.method.method = sm::parse_method(method);
  o.method.M = M;
  o.method.grid_ratio = grid_ratio;
  o.method.fft_floor = fft_floor;
  o.integrator.rtol = rtol;
  o.integrator.atol = atol;
  o.integrator.stepper = sm::parse_stepper(stepper);
  o.convention = sm::parse_convention(convention);
  set_initial(o, initial);
  o.times = times;
  o.t_end = t_end;
  o.until_mean_mass = until_mean_mass;
  o.series_t_min = series_t_min;
  o.series_per_decade = per_decade;
  o.bins_per_decade = bins_per_decade;
  o.volume = volume;
  o.leak_tolerance = leak_tolerance;
  CollectedRows rows(table != "series", table != "distribution");
  std::ostringstream warn;
  const sm::RunSummary s = sm::run(o, rows, warn);
  py::dict d = rows.result();
  std::vector<std::string> warnings;
  std::istringstream lines(warn.str());
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) warnings.push_back(line);
  d["warnings"] = warnings;
  d["t"] = s.t;
  d["leaked_fraction"] = s.leaked_fraction;
  d["steps"] = s.steps;
  d["evaluations"] = s.evaluations;
  return d;
}

}  // namespace

void bind_smoluchowski(py::module_& m) {
  const sm::RunOptions d;  // the tool's defaults
  m.def("smoluchowski", &run, py::arg("kernel") = d.kernel, py::arg("method") = sm::method_name(d.method.method),
        py::arg("M") = d.method.M, py::arg("grid_ratio") = d.method.grid_ratio, py::arg("fft_floor") = d.method.fft_floor,
        py::arg("rtol") = d.integrator.rtol, py::arg("atol") = d.integrator.atol,
        py::arg("stepper") = sm::stepper_name(d.integrator.stepper), py::arg("convention") = "half",
        py::arg("initial") = d.initial, py::arg("times") = std::vector<double>(), py::arg("t_end") = py::none(),
        py::arg("until_mean_mass") = py::none(), py::arg("table") = "distribution",
        py::arg("series_t_min") = d.series_t_min, py::arg("per_decade") = d.series_per_decade,
        py::arg("bins_per_decade") = d.bins_per_decade, py::arg("volume") = d.volume,
        py::arg("leak_tolerance") = d.leak_tolerance);
}

}  // namespace coolgas::python
