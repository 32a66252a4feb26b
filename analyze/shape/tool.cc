#include "analyze/shape/tool.h"

#include <ostream>
#include <sstream>

#include "analyze/shape/shape_table.h"
#include "common/trajectory/frame_reader.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

const char* table_name(ShapeTable t) {
  switch (t) {
    case ShapeTable::kMassRadius:
      return "mass-radius relation";
    case ShapeTable::kSeries:
      return "shape series";
    case ShapeTable::kClusters:
      return "cluster shapes";
  }
  return "";
}

const char* aggregates_text(int dimension) {
  if (dimension == 3)
    return "the aggregates of the file (ballistic aggregation) as solid spheres of diameter "
           "m^(1/3): their particles are not recorded, so d_f = 3 by construction";
  if (dimension == 2)
    return "the aggregates of the file (ballistic aggregation) as solid discs of diameter "
           "m^(1/2): their particles are not recorded, so d_f = 2 by construction";
  return "the aggregates of the file (ballistic aggregation) as solid rods of length m: their particles are not "
         "recorded, so d_f = 1 by construction";
}

std::string clusters_text(const Trajectory& traj) {
  if (traj.aggregates()) return aggregates_text(traj.dimension());
  static const char* const kTensor[4] = {"", "R_g^2 of its particle centres (the 1 x 1 gyration tensor)",
                                         "2 x 2 gyration tensor of its particle centres",
                                         "gyration tensor of its particle centres"};
  const Geometry g = traj.geometry();
  return cluster_cells_text(g) + "; each unwrapped along its own " + (g.d() == 1 ? "segments" : "cells") + "; " +
         kTensor[g.d()];
}

Provenance provenance(const Trajectory& traj, const ShapeOptions& o, const Window& fit) {
  Provenance p = traj.provenance();
  p.emplace_back("table", table_name(o.table));
  p.emplace_back("clusters", clusters_text(traj));
  p.emplace_back("bins_per_decade", std::to_string(o.bins_per_decade));
  p.emplace_back("fit_mass", fit.text());
  p.emplace_back("d_f", "unweighted fit of <ln R_g> = <ln m>/d_f + c over the mass bins in fit_mass; "
                        "clusters that wrap around the box and single points left out");
  if (o.table == ShapeTable::kClusters) p.emplace_back("min_mass", std::to_string(o.min_mass));
  for (double t : o.times) p.emplace_back("time", format_number(t));
  return p;
}

}  // namespace

void run_shape(const ShapeOptions& opt, std::ostream& final_out) {
  check_shape_options(opt.bins_per_decade, opt.min_mass);
  const Window fit = parse_window(opt.fit_mass, "--fit-mass");
  Trajectory traj(opt.input, kPosition | kAnyDimension);
  const Geometry g = traj.geometry();
  std::ostringstream os;  // written only when every dump has been read
  TsvWriter out(os, "coolgas-shape", provenance(traj, opt, fit), shape_columns(opt.table, g));
  ClusterShapes shapes;
  Frame buffer;
  traj.for_each_dump(traj.dumps_nearest(opt.times, opt.exact_time), buffer, [&](const Frame& frame) {
    const std::vector<ClusterShape> s =
        traj.aggregates() ? aggregate_shapes(frame.mass, g)
                          : shapes.of_particles(cluster_grid_of_dump(frame.L, traj.path(), frame.dump, g), frame.position);
    const TableBlock b =
        shape_block(opt.table, frame.time, s, mass_radius(s, opt.bins_per_decade, fit), opt.min_mass, g);
    if (opt.table == ShapeTable::kSeries) out.append(b);  // a row per dump, not a block
    else out.write(b);
  });
  final_out << os.str();
}

}  // namespace coolgas
