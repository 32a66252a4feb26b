#include "analyze/clusters/tool.h"

#include <cmath>
#include <optional>
#include <ostream>
#include <span>
#include <sstream>

#include "analyze/clusters/cluster_table.h"
#include "common/trajectory/frame_reader.h"
#include "common/trajectory/species_selection.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

// The particles one dump labels: every particle, or with --species K those of
// species K alone; with the diameters of a mixture's particles (empty for
// unit particles and for the unit cells, which take centres only).
struct Labelled {
  std::span<const double> position, diameter;
  std::vector<double> own_position, own_diameter;  // species K's, packed

  void select(const Frame& frame, std::optional<int> species, const std::string& where) {
    position = frame.position, diameter = frame.diameter;
    if (!species) return;
    position = species_values(frame.position, 3, frame.species, *species, own_position);
    if (!diameter.empty()) diameter = species_values(frame.diameter, 1, frame.species, *species, own_diameter);
    if (position.empty()) throw InputError(where + ": no particle of species " + std::to_string(*species));
  }
};

}  // namespace

void run_clusters(const ClustersOptions& opt, std::ostream& final_out) {
  // The table is built in memory and written only when every dump has been
  // read: a bad dump leaves no half table behind.
  std::ostringstream os;
  if (opt.bins_per_decade < 1)
    throw InputError("--bins-per-decade must be >= 1, got " + std::to_string(opt.bins_per_decade));
  const ClusterDefinition definition = parse_cluster_definition(opt.definition);
  // Contacts read a mixture's diameters (its species'); the unit cells take centres only.
  Trajectory traj(opt.input, kPosition | kAnyDimension | (opt.species ? kSpecies : 0u) |
                                 (definition.contact() ? kDiameter : 0u));
  check_species_option(traj, opt.species);
  const Geometry g = traj.geometry();
  Provenance prov = traj.provenance();
  prov.emplace_back("bins_per_decade", std::to_string(opt.bins_per_decade));
  if (traj.aggregates() && definition.contact())
    throw InputError("--definition " + definition_name(definition) + ": " + opt.input +
                     " is a ballistic-aggregation file, whose clusters are its aggregates");
  if (traj.aggregates())  // ballistic aggregation: the clusters are the aggregates themselves
    prov.emplace_back("clusters", "the aggregates of the file (ballistic aggregation); mass in particles");
  else if (definition.contact())
    prov.emplace_back("contact", contact_text(definition, traj.species_count() > 0));
  else
    prov.emplace_back("cells", cluster_cells_text(g));
  prov.emplace_back("definition", definition_name(definition));
  if (opt.species) prov.emplace_back("species", std::to_string(*opt.species));
  for (double t : opt.times) prov.emplace_back("time", format_number(t));
  if (opt.series && opt.scaled) throw InputError("--series and --scaled exclude each other: choose one table");
  prov.emplace_back("table", opt.series ? "cluster series" : (opt.scaled ? "scaled mass distribution" : "mass distribution"));
  const ClusterTable table =
      opt.series ? ClusterTable::kSeries : (opt.scaled ? ClusterTable::kScaled : ClusterTable::kDistribution);
  TsvWriter out(os, "coolgas-clusters", prov, cluster_columns(table));

  // Masses run from 1 to the particles labelled: N, or species K's alone,
  // whose bins then end where a file of its particles alone ends them.
  std::optional<MassHistogram> hist;
  std::int64_t most = 0;
  Labellers labellers;
  Labelled labelled;
  Frame buffer;
  traj.for_each_dump(traj.dumps_nearest(opt.times, opt.exact_time), buffer, [&](const Frame& frame) {
    const std::string where = traj.path() + ": dump " + std::to_string(frame.dump);
    labelled.select(frame, opt.species, where);
    const std::int64_t n = opt.species ? std::int64_t(labelled.position.size() / 3) : traj.particles();
    if (n != most) {
      most = n;
      hist.emplace(opt.bins_per_decade, n);
    }
    // ballistic aggregation: the clusters are the aggregates themselves
    if (definition.contact()) check_cutoff(definition, frame.L, where, labelled.diameter);
    else if (!traj.aggregates()) cluster_grid_of_dump(frame.L, traj.path(), frame.dump, g);  // a bad box names the dump
    fill_cluster_masses(*hist, labellers, definition, frame.L, labelled.position,
                        traj.aggregates() ? std::span<const double>(frame.mass) : std::span<const double>(), g,
                        labelled.diameter);
    const TableBlock b = cluster_block(table, frame.time, frame.L, *hist, g);
    if (table == ClusterTable::kSeries) out.append(b);  // a row per dump, not a block
    else out.write(b);
  });
  final_out << os.str();
}

}  // namespace coolgas
