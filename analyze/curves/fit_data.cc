#include "analyze/curves/fit_data.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "common/error.h"

namespace coolgas {
namespace {

std::optional<double> parse_bound(const std::string& s, const std::string& option, const std::string& text) {
  if (s.empty()) return std::nullopt;
  double x = 0;
  auto res = std::from_chars(s.data(), s.data() + s.size(), x);
  if (res.ec != std::errc() || res.ptr != s.data() + s.size() || !std::isfinite(x))
    throw InputError(option + " '" + text + "': '" + s + "' is not a finite number (expected LO:HI, e.g. 10:1e4)");
  return x;
}

}  // namespace

std::string Window::text() const {
  return (lo ? format_number(*lo) : std::string()) + ":" + (hi ? format_number(*hi) : std::string());
}

Window parse_window(const std::string& text, const std::string& option) {
  const auto colon = text.find(':');
  if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos)
    throw InputError(option + " '" + text + "' is not of the form LO:HI (either side may be empty, e.g. 10:1e4 or 100:)");
  Window w{parse_bound(text.substr(0, colon), option, text), parse_bound(text.substr(colon + 1), option, text)};
  if (w.lo && w.hi && *w.lo >= *w.hi)
    throw InputError(option + " '" + text + "' is empty; LO must be below HI");
  return w;
}

std::string error_column(const Table& table, const FitColumns& columns) {
  if (!columns.weights) return "";
  if (columns.err) return *columns.err;
  // The automatic choice falls back to no weights when some error is 0, as in
  // the table of a single run, instead of refusing it.
  const std::string guess = columns.E + "_err";
  if (std::find(table.columns.begin(), table.columns.end(), guess) == table.columns.end()) return "";
  const auto v = table.column_values(guess);
  return std::all_of(v.begin(), v.end(), [](double e) { return e > 0; }) ? guess : "";
}

FitData select_fit_data(const Table& table, const FitColumns& columns, const Window& window, std::size_t min_points) {
  const std::size_t ct = table.column(columns.t), ce = table.column(columns.E);
  const std::string err = error_column(table, columns);
  const std::size_t cerr = err.empty() ? 0 : table.column(err);
  FitData d;
  for (const auto& row : table.rows) {
    if (!window.contains(row[ct])) continue;
    d.t.push_back(row[ct]);
    d.E.push_back(row[ce]);
    if (err.empty()) continue;
    if (!(row[cerr] > 0))
      throw InputError(table.source + ": error column '" + err + "' holds " + format_number(row[cerr]) + " at " +
                       columns.t + " = " + format_number(row[ct]) +
                       "; weights need errors > 0 (a single run has none: pass --no-weights)");
    d.err.push_back(row[cerr]);
  }
  if (d.t.size() < min_points)
    throw InputError(table.source + ": " + std::to_string(d.t.size()) + " rows with " + columns.t + " in the window " +
                     window.text() + ", the fit needs at least " + std::to_string(min_points));
  return d;
}

}  // namespace coolgas
