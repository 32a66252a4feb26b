#include "analyze/fit/table.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <ostream>

#include "analyze/fit/haff.h"
#include "analyze/fit/local_slope.h"
#include "analyze/curves/power_law.h"
#include "analyze/curves/scaling_window.h"
#include "common/tool_main.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

constexpr const char* kTool = "coolgas-fit";

Provenance fit_provenance(const Table& table, const FitOptions& o, const char* mode) {
  const std::string err = error_column(table, o.columns);
  return {{"input", table.source},
          {"mode", mode},
          {"t_column", o.columns.t},
          {"E_column", o.columns.E},
          {"weights", err.empty() ? "none" : "1/" + err + "^2"},
          {"window", o.window.text()}};
}

// One row of results, or (--curve) the data with the fitted curve beside it
// and the results as provenance lines.
void write_result(const Table& table, const FitOptions& o, const FitData& d, const char* mode,
                  const std::vector<std::pair<std::string, double>>& results,
                  const std::function<double(double)>& model, std::ostream& out) {
  Provenance p = fit_provenance(table, o, mode);
  if (o.curve) {
    for (const auto& [k, v] : results) p.emplace_back(k, format_number(v));
    TsvWriter w(out, kTool, p, {o.columns.t, o.columns.E, o.columns.E + "_fit"});
    for (std::size_t i = 0; i < d.t.size(); ++i) w.row({d.t[i], d.E[i], model(d.t[i])});
    return;
  }
  std::vector<std::string> names;
  std::vector<double> values;
  for (const auto& [k, v] : results) names.push_back(k), values.push_back(v);
  TsvWriter w(out, kTool, p, names);
  w.row(values);
}

void write_power_law(const Table& table, const FitOptions& o, std::ostream& out) {
  const FitData d = select_fit_data(table, o.columns, o.window, 3);
  const PowerLawFit f = fit_power_law(d);
  write_result(table, o, d, "power",
               {{"theta", f.theta}, {"theta_err", f.theta_err}, {"A", f.A}, {"A_err", f.A_err},
                {"t_min", d.t.front()}, {"t_max", d.t.back()}, {"points", double(f.points)}, {"chi2_dof", f.chi2_dof}},
               [&](double t) { return f.A * std::pow(t, -f.theta); }, out);
}

void write_haff(const Table& table, const FitOptions& o, std::ostream& out) {
  const FitData d = select_fit_data(table, o.columns, o.window, 3);
  const HaffFit f = fit_haff(d);
  write_result(table, o, d, "haff",
               {{"E0", f.E0}, {"E0_err", f.E0_err}, {"t0", f.t0}, {"t0_err", f.t0_err},
                {"t_min", d.t.front()}, {"t_max", d.t.back()}, {"points", double(f.points)}, {"chi2_dof", f.chi2_dof}},
               [&](double t) { return f.E0 / ((1 + t / f.t0) * (1 + t / f.t0)); }, out);
}

void write_local_slope(const Table& table, const FitOptions& o, std::ostream& out) {
  FitColumns unweighted = o.columns;
  unweighted.weights = false;
  const auto slopes = local_slope(select_fit_data(table, unweighted, o.window, 3), o.smooth_decades);
  Provenance p = fit_provenance(table, FitOptions{o.input, o.mode, unweighted, o.window, false, o.smooth_decades, false},
                                "local-slope");
  p.emplace_back("smooth_decades", format_number(o.smooth_decades));
  TsvWriter w(out, kTool, p, {o.columns.t, "slope"});
  for (const auto& s : slopes) w.row({s.t, s.slope});
}

// Without --t-window a power law of the energy is fitted over the scaling
// window's rule; of any other column (M_max, L_t, N(m)) over t > 0.
FitOptions with_default_window(const Table& table, FitOptions o) {
  if (o.columns.E == "E" || o.columns.E == "E_over_E0") {
    const ChosenWindow c = scaling_window(table, o.columns);
    note(c.rule);
    o.window = c.window;
    return o;
  }
  const auto t = table.column_values(o.columns.t);
  if (std::any_of(t.begin(), t.end(), [](double x) { return !(x > 0); })) {
    o.window = Window{std::nextafter(0.0, 1.0), std::nullopt};
    note("no --t-window: fitting " + o.columns.t + " > 0 (a power law has no point at " + o.columns.t + " <= 0)");
  }
  return o;
}

}  // namespace

void write_fit_table(const FitOptions& options, std::ostream& out) {
  const Table table = read_table(options.input);
  switch (options.mode) {
    case FitMode::kPowerLaw:
      write_power_law(table, options.auto_window ? with_default_window(table, options) : options, out);
      break;
    case FitMode::kHaff: write_haff(table, options, out); break;
    case FitMode::kLocalSlope: write_local_slope(table, options, out); break;
  }
}

}  // namespace coolgas
