#include "analyze/structure/tool.h"

#include <ostream>
#include <sstream>

#include "analyze/structure/structure_table.h"
#include "common/trajectory/frame_reader.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/memory.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

const char* table_name(StructureTable t) {
  switch (t) {
    case StructureTable::kSpectrum:
      return "structure factor";
    case StructureTable::kSeries:
      return "growing length series";
    case StructureTable::kCorrelation:
      return "pair correlation";
    case StructureTable::kRdf:
      return "radial distribution";
    case StructureTable::kRdfSeries:
      return "contact value series";
  }
  return "";
}

Provenance provenance(const Trajectory& traj, const StructureOptions& o, int n, double L) {
  const Geometry g = traj.geometry();
  static const char* const kPoints[4] = {"", " points on the ring", "^2 points", "^3 points"};  // by d
  const std::string points = kPoints[g.d()];
  Provenance p = traj.provenance();
  p.emplace_back("table", table_name(o.table));
  p.emplace_back("density", traj.aggregates() ? "aggregates weighted by their mass (ballistic aggregation): S of "
                                                 "their particles, each at its aggregate's centre"
                                               : "particles, unit weight");
  p.emplace_back("grid", std::to_string(n) + points + ", spacing " + format_number(L / n) + " sigma");
  p.emplace_back("assignment", "cloud in cell; S = s + (|rho_grid|^2/M - s C1)/W^2 (Jing 2005, ApJ 620, 559)");
  p.emplace_back("shells", "|k| L/(2 pi) rounded, 1 .. grid/4 (k up to half the grid's Nyquist wave number)");
  p.emplace_back("peak_fraction", format_number(o.peak_fraction));
  p.emplace_back("L_t", "2 pi / <k>, first moment of S over the low-k peak (cut: S - s <= peak_fraction (S_max - s))");
  p.emplace_back("direct_shells", std::to_string(o.direct_shells));
  for (double t : o.times) p.emplace_back("time", format_number(t));
  return p;
}

Provenance rdf_provenance(const Trajectory& traj, const StructureOptions& o, double r_max) {
  Provenance p = traj.provenance();
  p.emplace_back("table", table_name(o.table));
  p.emplace_back("bins", "r in [i, i + 1)/" + std::to_string(o.bins_per_sigma) + " sigma up to r_max = " +
                             format_number(r_max) + " sigma; periodic minimum images");
  p.emplace_back("normalisation", "g = pairs / (N (N - 1) / 2 * shell measure / L^d): 1 for an ideal gas of the same N");
  p.emplace_back("contact", "g(sigma+): maximum-likelihood fit of g(sigma+) exp(-kappa (r - sigma)) to the pair counts "
                            "(Poisson) of the " + std::to_string(o.contact_bins) + " bins above sigma");
  p.emplace_back("g_equilibrium", std::string("the equilibrium contact value at the frame's phi: ") +
                                      traj.geometry().contact_value_name());
  for (double t : o.times) p.emplace_back("time", format_number(t));
  return p;
}

// --rdf: g(r) or its contact value, for the particles of a gas file.
void run_rdf(const StructureOptions& opt, const Trajectory& traj, const std::vector<std::size_t>& dumps,
             std::ostream& final_out) {
  if (traj.aggregates())
    throw InputError("--rdf: " + opt.input + " is a ballistic-aggregation file; g(r) is for particles of one diameter");
  const double r_max = rdf_range(opt.r_max, traj.box_side(dumps.front()), opt.bins_per_sigma, opt.contact_bins);
  std::ostringstream os;  // written only when every dump has been read
  TsvWriter out(os, "coolgas-structure", rdf_provenance(traj, opt, r_max), structure_columns(opt.table));
  PairDistances pairs(traj.geometry(), r_max, opt.bins_per_sigma);
  Frame buffer;
  traj.for_each_dump(dumps, buffer, [&](const Frame& frame) {
    if (frame.L != traj.box_side(dumps.front())) rdf_range(opt.r_max, frame.L, opt.bins_per_sigma, opt.contact_bins);
    const TableBlock b = rdf_block(opt.table, pairs, frame.time, frame.L, frame.position, opt.contact_bins, traj.geometry());
    if (opt.table == StructureTable::kRdfSeries) out.append(b);
    else out.write(b);
  });
  final_out << os.str();
}

std::span<const double> frame_weights(const Trajectory& traj, const Frame& f) {
  return traj.aggregates() ? std::span<const double>(f.mass) : std::span<const double>();
}

}  // namespace

void run_structure(const StructureOptions& opt, std::ostream& final_out) {
  check_structure_options(opt.grid, opt.peak_fraction, opt.direct_shells);
  check_rdf_options(opt.r_max, opt.bins_per_sigma, opt.contact_bins);
  const bool velocity = opt.table == StructureTable::kSeries || opt.table == StructureTable::kCorrelation;
  Trajectory traj(opt.input, (velocity ? (kPosition | kVelocity) : kPosition) | kAnyDimension);
  const std::vector<std::size_t> dumps = traj.dumps_nearest(opt.times, opt.exact_time);
  if (dumps.empty()) throw InputError(opt.input + ": the trajectory holds no dumps");
  if (is_rdf(opt.table)) return run_rdf(opt, traj, dumps, final_out);
  const double L = traj.box_side(dumps.front());
  const int n = structure_grid_points(opt.grid, L, traj.geometry(), usable_memory_bytes());
  std::ostringstream os;  // written only when every dump has been read
  TsvWriter out(os, "coolgas-structure", provenance(traj, opt, n, L), structure_columns(opt.table));
  FrameStructure fs(n, traj.geometry());
  Frame buffer;
  traj.for_each_dump(dumps, buffer, [&](const Frame& frame) {
    const TableBlock b = structure_block(opt.table, fs, frame.time, frame.L, frame.position, frame.velocity,
                                         frame_weights(traj, frame), opt.peak_fraction, opt.direct_shells);
    if (opt.table == StructureTable::kSeries) out.append(b);  // a row per dump, not a block
    else out.write(b);
  });
  final_out << os.str();
}

}  // namespace coolgas
