#include "analyze/clusters/tool.h"

#include <cmath>

#include <ostream>
#include <span>
#include <sstream>

#include "analyze/clusters/cluster_table.h"
#include "common/trajectory/frame_reader.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {

void run_clusters(const ClustersOptions& opt, std::ostream& final_out) {
  // The table is built in memory and written only when every dump has been
  // read: a bad dump leaves no half table behind.
  std::ostringstream os;
  if (opt.bins_per_decade < 1)
    throw InputError("--bins-per-decade must be >= 1, got " + std::to_string(opt.bins_per_decade));
  const ClusterDefinition definition = parse_cluster_definition(opt.definition);
  Trajectory traj(opt.input, kPosition | kAnyDimension);
  const Geometry g = traj.geometry();
  Provenance prov = traj.provenance();
  prov.emplace_back("bins_per_decade", std::to_string(opt.bins_per_decade));
  if (traj.aggregates() && definition.contact())
    throw InputError("--definition " + definition_name(definition) + ": " + opt.input +
                     " is a ballistic-aggregation file, whose clusters are its aggregates");
  if (traj.aggregates())  // ballistic aggregation: the clusters are the aggregates themselves
    prov.emplace_back("clusters", "the aggregates of the file (ballistic aggregation); mass in particles");
  else if (definition.contact())
    prov.emplace_back("contact", contact_text(definition));
  else
    prov.emplace_back("cells", cluster_cells_text(g));
  prov.emplace_back("definition", definition_name(definition));
  for (double t : opt.times) prov.emplace_back("time", format_number(t));
  if (opt.series && opt.scaled) throw InputError("--series and --scaled exclude each other: choose one table");
  prov.emplace_back("table", opt.series ? "cluster series" : (opt.scaled ? "scaled mass distribution" : "mass distribution"));
  const ClusterTable table =
      opt.series ? ClusterTable::kSeries : (opt.scaled ? ClusterTable::kScaled : ClusterTable::kDistribution);
  TsvWriter out(os, "coolgas-clusters", prov, cluster_columns(table));

  MassHistogram hist(opt.bins_per_decade, traj.particles());
  Labellers labellers;
  Frame buffer;
  traj.for_each_dump(traj.dumps_nearest(opt.times, opt.exact_time), buffer, [&](const Frame& frame) {
    // ballistic aggregation: the clusters are the aggregates themselves
    if (definition.contact()) check_cutoff(definition, frame.L, traj.path() + ": dump " + std::to_string(frame.dump));
    else if (!traj.aggregates()) cluster_grid_of_dump(frame.L, traj.path(), frame.dump, g);  // a bad box names the dump
    fill_cluster_masses(hist, labellers, definition, frame.L, frame.position,
                        traj.aggregates() ? std::span<const double>(frame.mass) : std::span<const double>(), g);
    const TableBlock b = cluster_block(table, frame.time, frame.L, hist, g);
    if (table == ClusterTable::kSeries) out.append(b);  // a row per dump, not a block
    else out.write(b);
  });
  final_out << os.str();
}

}  // namespace coolgas
