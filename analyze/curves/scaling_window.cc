#include "analyze/curves/scaling_window.h"

#include <cmath>
#include <cstdio>

#include "common/dimension_line.h"
#include "common/error.h"

namespace coolgas {

namespace {

constexpr double kQuarterDecade = 1.778;  // 10^(1/4), rounded as pipelines/exponents.sh has it
constexpr double kBurgers = 1.5;
constexpr double kCrossoverX = 0.1;  // x = t / L^z at the finite-size crossover

std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::optional<double> box_side(const Table& table) {
  const auto L = table.get("L");
  if (!L) return std::nullopt;
  try {
    const double v = std::stod(*L);
    if (v > 0 && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> past_haff(const Table& table, const FitColumns& columns, double t_end) {
  const std::vector<double> t = table.column_values(columns.t), E = table.column_values(columns.E);
  std::optional<double> steep;  // first t with slope >= 1
  bool haff = false;
  for (std::size_t i = 0; i < t.size() && t[i] <= t_end; ++i) {
    if (!(t[i] > 0 && E[i] > 0)) continue;
    std::size_t j = i + 1;
    while (j < t.size() && t[j] < t[i] * kQuarterDecade) ++j;
    if (j == t.size() || !(E[j] > 0)) break;  // no quarter decade left to judge
    const double slope = -std::log(E[j] / E[i]) / std::log(t[j] / t[i]);
    if (!steep && slope >= 1) steep = t[i];
    if (!steep) continue;
    if (slope > kBurgers) haff = true;
    else if (haff) return t[i];
  }
  return haff ? std::nullopt : steep;
}

double crossover_z(int dimension) { return (dimension + 2) / 2.0; }

// z = (d+2)/2 written as the papers write it: L^2 in 2D, L^(5/2) and L^(3/2) in 3D and 1D.
std::string crossover_text(const Table& table) {
  const int d = dimension_of(table);
  std::string text = "0.1 L^";  // appended piece by piece: GCC 12 warns falsely on "(" + std::string
  if (d % 2 == 0) return text += std::to_string((d + 2) / 2);
  text += "(";
  text += std::to_string(d + 2);
  return text += "/2)";
}

double finite_size_crossover(const Table& table) {
  const auto L = box_side(table);
  return L ? kCrossoverX * std::pow(*L, crossover_z(dimension_of(table))) : INFINITY;
}

ChosenWindow scaling_window(const Table& table, const FitColumns& columns) {
  const double end = finite_size_crossover(table);
  const auto start = past_haff(table, columns, end);
  if (!start)
    throw InputError(table.source + ": give --t-window TMIN:TMAX: " + columns.E +
                     "(t) does not leave Haff's law (t^-1, then no steeper than t^-3/2)" +
                     (std::isfinite(end) ? " before " + crossover_text(table) + " = " + short_number(end) : std::string()));
  ChosenWindow c;
  c.window.lo = *start;
  c.rule = "no --t-window: fitting t >= " + short_number(*start) + " (past Haff's law: t^-1 to t^-3/2)";
  if (std::isfinite(end)) {
    c.window.hi = end;
    c.rule = "no --t-window: fitting t = " + short_number(*start) + " to " + short_number(end) +
             " (past Haff's law: t^-1 to t^-3/2; before the finite-size crossover " + crossover_text(table) + ", L = " +
             short_number(*box_side(table)) + ")";
  }
  return c;
}

}  // namespace coolgas
