#include "analyze/shape/tool.h"

#include <ostream>
#include <sstream>

#include "analyze/shape/cluster_shapes.h"
#include "analyze/shape/mass_radius.h"
#include "common/trajectory/frame_reader.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

std::vector<std::string> columns(ShapeTable t) {
  switch (t) {
    case ShapeTable::kMassRadius:
      return {"t", "m", "dm", "clusters", "Rg", "Rg_err", "asphericity", "prolateness"};
    case ShapeTable::kSeries:
      return {"t", "d_f", "d_f_err", "fit_bins", "fitted_clusters", "asphericity", "prolateness", "wrapping_fraction"};
    case ShapeTable::kClusters:
      return {"t", "mass", "Rg", "lambda1", "lambda2", "lambda3", "asphericity", "prolateness", "wraps"};
  }
  return {};
}

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

Provenance provenance(const Trajectory& traj, const ShapeOptions& o, const Window& fit) {
  Provenance p = traj.provenance();
  p.emplace_back("table", table_name(o.table));
  if (traj.aggregates())
    p.emplace_back("clusters", "the aggregates of the file (ballistic aggregation) as solid spheres of diameter "
                               "m^(1/3): their particles are not recorded, so d_f = 3 by construction");
  else
    p.emplace_back("clusters", "floor(L)^3 cubic cells of side L/floor(L); face neighbours; periodic; each unwrapped "
                               "along its own cells; gyration tensor of its particle centres");
  p.emplace_back("bins_per_decade", std::to_string(o.bins_per_decade));
  p.emplace_back("fit_mass", fit.text());
  p.emplace_back("d_f", "unweighted fit of <ln R_g> = <ln m>/d_f + c over the mass bins in fit_mass; "
                        "clusters that wrap around the box and single points left out");
  if (o.table == ShapeTable::kClusters) p.emplace_back("min_mass", std::to_string(o.min_mass));
  for (double t : o.times) p.emplace_back("time", format_number(t));
  return p;
}

std::string summary(double t, const MassRadius& mr) {
  return "t = " + format_number(t) + "; d_f = " + format_number(mr.d_f) + " +- " + format_number(mr.d_f_err) + " (" +
         std::to_string(mr.fit_bins) + " bins); wrapping_fraction = " + format_number(mr.wrapping_fraction);
}

void write_frame(TsvWriter& out, const ShapeOptions& o, double t, const std::vector<ClusterShape>& shapes,
                 const MassRadius& mr) {
  switch (o.table) {
    case ShapeTable::kMassRadius:
      out.block(summary(t, mr));
      for (const MassRadiusBin& b : mr.bins)
        out.row({t, b.m, double(b.dm), double(b.clusters), b.Rg, b.Rg_err, b.asphericity, b.prolateness});
      return;
    case ShapeTable::kSeries:
      out.row({t, mr.d_f, mr.d_f_err, double(mr.fit_bins), double(mr.fitted_clusters), mr.asphericity,
               mr.prolateness, mr.wrapping_fraction});
      return;
    case ShapeTable::kClusters:
      out.block(summary(t, mr));
      for (const ClusterShape& c : shapes) {
        if (c.shape.mass < o.min_mass) break;  // ranked by mass
        const Shape& s = c.shape;
        out.row({t, double(s.mass), s.Rg, s.lambda[0], s.lambda[1], s.lambda[2], s.asphericity, s.prolateness,
                 c.wraps ? 1.0 : 0.0});
      }
      return;
  }
}

}  // namespace

void run_shape(const ShapeOptions& opt, std::ostream& final_out) {
  if (opt.bins_per_decade < 1)
    throw InputError("--bins-per-decade must be >= 1, got " + std::to_string(opt.bins_per_decade));
  if (opt.min_mass < 1) throw InputError("--min-mass must be >= 1, got " + std::to_string(opt.min_mass));
  const Window fit = parse_window(opt.fit_mass, "--fit-mass");
  Trajectory traj(opt.input, kPosition);
  std::ostringstream os;  // written only when every dump has been read
  TsvWriter out(os, "coolgas-shape", provenance(traj, opt, fit), columns(opt.table));
  ClusterShapes shapes;
  Frame frame;
  const std::vector<std::size_t> dumps = traj.dumps_nearest(opt.times, opt.exact_time);
  for (std::size_t i = 0; i < dumps.size(); ++i) {
    throw_if_interrupted(i, dumps.size(), "dumps");
    traj.read(dumps[i], frame);
    const std::vector<ClusterShape> s =
        traj.aggregates() ? aggregate_shapes(frame.mass) : shapes.of_particles(cluster_grid_of_dump(frame.L, traj.path(), frame.dump), frame.position);
    write_frame(out, opt, frame.time, s, mass_radius(s, opt.bins_per_decade, fit));
  }
  final_out << os.str();
}

}  // namespace coolgas
