// The coolgas-fit tool: a table in (path or "-"), fit results out
// (data-schema/tsv-tables.md, section coolgas-fit).
#pragma once
#include <iosfwd>
#include <string>

#include "analyze/curves/fit_data.h"

namespace coolgas {

enum class FitMode { kPowerLaw, kLocalSlope, kHaff };

struct FitOptions {
  std::string input = "-";
  FitMode mode = FitMode::kPowerLaw;
  FitColumns columns;
  Window window;
  bool auto_window = false;      // no --t-window given: --power picks its window (analyze/curves/scaling_window.h)
  double smooth_decades = 0.25;  // local slope: half width of the smoothing window
  bool curve = false;            // power/Haff: write t, E, E_fit rows instead of one result row
};

void write_fit_table(const FitOptions& options, std::ostream& out);

}  // namespace coolgas
