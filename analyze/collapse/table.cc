#include "analyze/collapse/table.h"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "analyze/collapse/fixed_product.h"
#include "analyze/collapse/quality.h"
#include "analyze/collapse/seed_weights.h"
#include "analyze/collapse/tail.h"
#include "analyze/curves/scaling_window.h"
#include "common/dimension_line.h"
#include "common/error.h"
#include "common/tool_main.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

constexpr const char* kTool = "coolgas-collapse";

// The tables grouped by L, in increasing L: a deterministic block order for gnuplot's index.
// The collapse spans the finite-size crossover on purpose, so the default
// window (analyze/curves/scaling_window.h) has only its start: the latest t
// at which a table leaves Haff's law.
Window default_window(const std::vector<Table>& tables, const FitColumns& columns) {
  Window w;
  for (const auto& table : tables) {
    const auto start = past_haff(table, columns, finite_size_crossover(table));
    if (!start)
      throw InputError(table.source + ": --optimize needs --t-window TMIN: here: " + columns.E +
                       "(t) does not leave Haff's law (t^-1, then no steeper than t^-3/2) before the finite-size "
                       "crossover " + crossover_text(table));
    w.lo = std::max(w.lo.value_or(0.0), *start);
  }
  note("--optimize without --t-window: collapsing t >= " + format_number(*w.lo) +
       " (every table past Haff's law there: t^-1 to t^-3/2)");
  return w;
}

void check_min_overlap(const CollapseOptions& o) {
  if (!(o.search.min_overlap_decades >= 0))
    throw InputError("--min-overlap " + format_number(o.search.min_overlap_decades) + " is not allowed; it must be >= 0");
}

// The one dimension of all tables: a collapse compares boxes of one dimension.
int common_dimension(const std::vector<Table>& tables) {
  const int d = dimension_of(tables.front());
  for (const auto& table : tables)
    if (dimension_of(table) != d)
      throw InputError("tables of different dimensions cannot be collapsed together: " + tables.front().source +
                       " is " + std::to_string(d) + "D, " + table.source + " is " + std::to_string(dimension_of(table)) +
                       "D (the '# dimension:' line; none = 3D); collapse each dimension on its own");
  return d;
}

// --z-theta is any product; the mean-field relation is z theta = d, so a
// different value for these tables' d is said on stderr (it may be meant).
void note_z_theta(const CollapseOptions& o, int dimension) {
  if (!o.optimize || !o.z_theta || *o.z_theta == dimension) return;
  note("--z-theta " + format_number(*o.z_theta) + " with " + std::to_string(dimension) +
       "D tables: the mean-field relation there is z theta = d = " + std::to_string(dimension));
}

std::vector<SizeEnsemble> load_sizes(const std::vector<Table>& tables, CollapseOptions& o) {
  if (tables.empty()) throw InputError("no E(t) tables given (usage: coolgas-collapse TABLE...)");
  note_z_theta(o, common_dimension(tables));
  if (o.auto_window) o.t_window = default_window(tables, o.columns);
  std::vector<ScalingCurve> curves;
  for (const auto& table : tables) curves.push_back(make_scaling_curve(table, o.columns, o.t_window));
  auto sizes = group_by_size(curves);
  if (o.seed_weights)
    for (auto& s : sizes) estimate_seed_scatter(s);
  return sizes;
}

std::string uncertainty_text(const CollapseFit& fit, std::uint64_t seed) {
  if (fit.kind == BootstrapKind::kRuns)
    return "jackknife over whole runs (one table per seed), " + std::to_string(fit.replicas) + " replicas";
  const char* kind = fit.kind == BootstrapKind::kErrors
                         ? "parametric bootstrap over the E errors (treats times as independent: too small for one "
                           "ensemble's time-correlated mean; give one table per seed instead), "
                         : "bootstrap over rows (underestimates; no E errors), ";
  return kind + std::to_string(fit.replicas) + " replicas, seed " + std::to_string(seed);
}

Provenance collapse_provenance(const CollapseOptions& o, const std::vector<SizeEnsemble>& sizes, const CollapseResult& r,
                               int dimension) {
  Provenance p;
  for (const auto& s : sizes)
    for (const auto& c : s.runs) p.emplace_back("input", c.source + " (L = " + format_number(c.L) + ")");
  add_dimension_line(p, dimension);
  p.emplace_back("t_window", o.t_window.text());
  p.emplace_back("min_overlap_decades", format_number(o.search.min_overlap_decades));
  p.emplace_back("weights", o.seed_weights ? "seeds: quality is a chi^2 per point, over the variance of ln E among "
                                             "each L's runs (+-" + std::to_string(kScatterRows) + " rows, at least " +
                                             format_number(kScatterFloor) + "^2)"
                                           : "none");
  if (o.optimize && o.z_theta)
    p.emplace_back("z_theta", format_number(*o.z_theta) + " (fixed: z optimised, theta = z_theta / z)");
  p.emplace_back("theta", format_number(r.theta));
  p.emplace_back("z", format_number(r.z));
  if (r.fit) {
    p.emplace_back("theta_err", format_number(r.fit->theta_err));
    p.emplace_back("z_err", format_number(r.fit->z_err));
    if (!o.z_theta) {  // the free fit's product, to set beside the fixed one's (--z-theta 3: mean field)
      p.emplace_back("z_theta", format_number(r.z * r.theta));
      p.emplace_back("z_theta_err", format_number(r.fit->z_theta_err));
    }
    p.emplace_back("uncertainty", uncertainty_text(*r.fit, o.search.seed));
  }
  p.emplace_back("quality", format_number(r.quality));
  if (o.eta_window) {
    p.emplace_back("eta", r.eta ? format_number(r.eta->theta) : "nan");
    p.emplace_back("eta_err", r.eta ? format_number(r.eta->theta_err) : "nan");
    p.emplace_back("eta_window", o.eta_window->text());
    if (!r.eta) p.emplace_back("eta_note", "fewer than 3 scaled points in the window");
  }
  return p;
}

std::vector<TableBlock> curve_blocks(const std::vector<ScalingCurve>& curves, const CollapseResult& r) {
  std::vector<TableBlock> blocks;
  for (const auto& c : curves) {
    // No "# L = ..." block comment: before the first row read_table would take
    // it for the column line; the L column says it instead.
    TableBlock& b = blocks.emplace_back();
    const double sx = std::exp(c.ln_x_shift(r.z)), sy = std::exp(c.ln_y_shift(r.theta, r.z));
    for (std::size_t i = 0; i < c.t.size(); ++i) b.rows.push_back({c.t[i] * sx, c.E[i] * sy, c.L, c.t[i], c.E[i]});
  }
  return blocks;
}

// Exponents so large that a scaled point overflows (--theta 1e308: E
// L^(z theta) = inf) or underflows to 0 would write inf, nan or 0 where the
// table promises a number: refused with one line before anything is written.
void check_scaled_points(const std::vector<ScalingCurve>& curves, const CollapseResult& r) {
  for (const auto& c : curves)
    for (std::size_t i = 0; i < c.t.size(); ++i) {
      const double x = c.t[i] * std::exp(c.ln_x_shift(r.z)), y = c.E[i] * std::exp(c.ln_y_shift(r.theta, r.z));
      if (std::isfinite(x) && std::isfinite(y) && x > 0 && y > 0 && std::isfinite(r.quality)) continue;
      throw InputError("theta = " + format_number(r.theta) + ", z = " + format_number(r.z) + " scale t = " +
                       format_number(c.t[i]) + " (L = " + format_number(c.L) + ") to x = " + format_number(x) +
                       ", y = " + format_number(y) + "; give exponents with finite, nonzero L^z and L^(z theta)");
    }
}

void summarise(const CollapseOptions& o, CollapseResult& r) {
  r.columns = {"theta", "theta_err", "z", "z_err", "quality"};
  std::vector<double> values{r.theta, r.fit ? r.fit->theta_err : 0, r.z, r.fit ? r.fit->z_err : 0, r.quality};
  if (o.eta_window) {  // the columns stay when the fit is impossible, so readers find them
    const double nan = std::nan("");
    r.columns.insert(r.columns.end(), {"eta", "eta_err"});
    values.insert(values.end(), {r.eta ? r.eta->theta : nan, r.eta ? r.eta->theta_err : nan});
  }
  r.blocks = {TableBlock{"", {values}}};
}

}  // namespace

CollapseResult collapse_tables(const std::vector<Table>& tables, const CollapseOptions& options) {
  check_min_overlap(options);
  CollapseOptions o = options;  // the default window, once chosen, goes into the provenance
  const auto sizes = load_sizes(tables, o);
  const auto curves = mean_curves(sizes);
  CollapseResult r;
  r.theta = o.theta;
  r.z = o.z;
  if (o.optimize) {
    CollapseSearch s = o.search;
    s.theta0 = o.theta;
    s.z0 = o.z;
    r.fit = o.z_theta ? optimize_collapse_fixed_product(sizes, s, *o.z_theta) : optimize_collapse(sizes, s);
    r.theta = r.fit->theta;
    r.z = r.fit->z;
  }
  r.quality = collapse_quality(curves, r.theta, r.z, o.search.min_overlap_decades);
  if (o.eta_window) r.eta = fit_tail_exponent(curves, r.theta, r.z, *o.eta_window);
  check_scaled_points(curves, r);
  r.provenance = collapse_provenance(o, sizes, r, dimension_of(tables.front()));
  if (o.summary) {
    summarise(o, r);
  } else {
    r.columns = {"x", "y", "L", "t", "E"};
    r.blocks = curve_blocks(curves, r);
  }
  return r;
}

void write_collapse_table(const CollapseOptions& options, std::ostream& out) {
  check_min_overlap(options);  // before any table is read
  std::vector<Table> tables;
  for (const auto& path : options.inputs) tables.push_back(read_table(path));
  const CollapseResult r = collapse_tables(tables, options);
  TsvWriter w(out, kTool, r.provenance, r.columns);
  for (const auto& b : r.blocks) {
    if (options.summary) w.append(b);
    else w.write(b);
  }
}

}  // namespace coolgas
