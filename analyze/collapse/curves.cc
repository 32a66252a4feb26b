#include "analyze/collapse/curves.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "common/error.h"

namespace coolgas {
namespace {

double read_L(const Table& table) {
  const auto text = table.get("L");
  if (!text)
    throw InputError(table.source + ": no '# L: <box side>' provenance line; make the table with coolgas-energy");
  double L = 0;
  auto res = std::from_chars(text->data(), text->data() + text->size(), L);
  if (res.ec != std::errc() || res.ptr != text->data() + text->size() || !(L > 0) || !std::isfinite(L))
    throw InputError(table.source + ": provenance 'L: " + *text + "' is not a box side (a number > 0)");
  return L;
}

}  // namespace

ScalingCurve make_scaling_curve(const Table& table, const FitColumns& columns, const Window& t_window) {
  ScalingCurve c;
  c.source = table.source;
  c.L = read_L(table);
  c.ln_L = std::log(c.L);
  const std::size_t ct = table.column(columns.t), ce = table.column(columns.E);
  const std::string err = error_column(table, columns);
  const std::size_t cerr = err.empty() ? 0 : table.column(err);
  for (const auto& row : table.rows) {
    const double t = row[ct], E = row[ce];
    if (!(t > 0) || !t_window.contains(t)) continue;
    if (!(E > 0))
      throw InputError(table.source + ": " + columns.E + " = " + format_number(E) + " at " + columns.t + " = " +
                       format_number(t) + " is not > 0; the collapse works with ln E");
    if (!c.t.empty() && t <= c.t.back())
      throw InputError(table.source + ": " + columns.t + " must increase down the table, but " + format_number(t) +
                       " follows " + format_number(c.t.back()));
    c.t.push_back(t);
    c.E.push_back(E);
    c.ln_t.push_back(std::log(t));
    c.ln_E.push_back(std::log(E));
    if (!err.empty()) c.ln_E_err.push_back(row[cerr] / E);
  }
  if (c.t.size() < 2)
    throw InputError(table.source + ": " + std::to_string(c.t.size()) + " rows with " + columns.t + " > 0 in the window " +
                     t_window.text() + "; a curve needs at least 2");
  return c;
}

double interpolate_clamped(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  const auto i = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin());
  const double u = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return ys[i - 1] + u * (ys[i] - ys[i - 1]);
}

ScalingCurve subset(const ScalingCurve& c, const std::vector<std::size_t>& rows) {
  ScalingCurve s;
  s.source = c.source;
  s.L = c.L;
  s.ln_L = c.ln_L;
  for (std::size_t i : rows) {
    s.t.push_back(c.t[i]);
    s.E.push_back(c.E[i]);
    s.ln_t.push_back(c.ln_t[i]);
    s.ln_E.push_back(c.ln_E[i]);
    if (!c.ln_E_err.empty()) s.ln_E_err.push_back(c.ln_E_err[i]);
    if (!c.ln_E_var.empty()) s.ln_E_var.push_back(c.ln_E_var[i]);
  }
  return s;
}

}  // namespace coolgas
