// The coolgas-collapse tool: E(t) tables of several L in, scaled curves (or a
// one-row summary) out (data-schema/tsv-tables.md, section coolgas-collapse).
#pragma once
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "analyze/collapse/optimize.h"
#include "analyze/curves/fit_data.h"
#include "analyze/curves/power_law.h"
#include "common/tsv.h"

namespace coolgas {

struct CollapseOptions {
  std::vector<std::string> inputs;  // E(t) tables, one or more (runs) per L ("-" at most once)
  FitColumns columns;               // t and E column names (errors unused)
  double theta = 1.2, z = 2.5;      // fixed scaling, or the optimiser's start
  bool optimize = false;
  CollapseSearch search;
  Window t_window;                  // rows used, in unscaled t
  bool auto_window = false;         // --optimize without --t-window: from where every table is past Haff's law
  std::optional<Window> eta_window; // fit f(x) ~ x^-eta over this x window
  bool summary = false;             // one row of results instead of the curves
  bool seed_weights = false;        // weigh the collapse by the scatter of each L's runs (seed_weights.h)
  std::optional<double> z_theta;    // --optimize with z theta held here, theta = z_theta / z (fixed_product.h)
};

// The collapse of E(t) tables already read (one or more per L; options.inputs
// unused): its provenance and the table's columns and blocks, one per L in
// increasing L, or the summary's one row. The tool writes it; the Python
// module (analyze/python/) returns it.
struct CollapseResult {
  Provenance provenance;
  std::vector<std::string> columns;
  std::vector<TableBlock> blocks;
  double theta = 0, z = 0, quality = 0;
  std::optional<CollapseFit> fit;   // with --optimize
  std::optional<PowerLawFit> eta;   // with an eta window, when 3 or more points lie in it
};
CollapseResult collapse_tables(const std::vector<Table>& tables, const CollapseOptions& options);

// Reads options.inputs and writes the table.
void write_collapse_table(const CollapseOptions& options, std::ostream& out);

}  // namespace coolgas
