// The (t, E, error) samples a fit works on, taken from a TSV table by column
// name and restricted to a window of t (coolgas-fit, coolgas-collapse).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "common/tsv.h"

namespace coolgas {

// Closed interval [lo, hi]; an absent end is unbounded. Parsed from "lo:hi",
// either side may be empty ("100:" = from 100 on).
struct Window {
  std::optional<double> lo, hi;
  bool contains(double x) const { return (!lo || x >= *lo) && (!hi || x <= *hi); }
  std::string text() const;  // "lo:hi" as given back to the user
};
// `option` names the command-line option in the error message.
Window parse_window(const std::string& text, const std::string& option);

struct FitData {
  std::vector<double> t, E;
  std::vector<double> err;  // standard errors of E; empty: unweighted
};

struct FitColumns {
  std::string t = "t", E = "E";
  std::optional<std::string> err;  // absent: "<E>_err" if the table has it and all its values are > 0
  bool weights = true;             // false: ignore any error column
};

// The rows of `table` whose t lies in `window`. InputError if fewer than
// `min_points` remain, or if an error column is used and holds a value <= 0.
FitData select_fit_data(const Table& table, const FitColumns& columns, const Window& window, std::size_t min_points);

// The error column select_fit_data uses for this table ("" if none).
std::string error_column(const Table& table, const FitColumns& columns);

}  // namespace coolgas
