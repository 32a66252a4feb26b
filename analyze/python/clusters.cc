// Clusters, wrapped: the paper's unit-cell labelling (analyze/labelling/) and
// the coolgas-clusters table of one frame (analyze/clusters/cluster_table.h),
// by either definition (--definition cells | contact[:CUTOFF]).
#include "analyze/clusters/cluster_table.h"
#include "analyze/labelling/particle_labels.h"
#include "analyze/python/arrays.h"
#include "common/limits.h"

namespace coolgas::python {
namespace {

ClusterTable table_of(const std::string& name) {
  return choice<ClusterTable>(name,
                              {{"distribution", ClusterTable::kDistribution},
                               {"scaled", ClusterTable::kScaled},
                               {"series", ClusterTable::kSeries}},
                              "table", "a cluster table");
}

// A mixture's diameters, one per position (none given: unit particles), each > 0.
std::vector<double> diameters(const std::optional<py::object>& given, std::size_t expected) {
  if (!given) return {};
  std::vector<double> s = values(*given, "diameters");
  if (s.size() != expected)
    throw InputError("diameters holds " + std::to_string(s.size()) + " values for " + std::to_string(expected) +
                     " positions; give one per position");
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!(s[i] > 0)) throw InputError("diameters[" + std::to_string(i) + "] = " + format_number(s[i]) + " is not > 0");
  return s;
}

// Labels and the size table: (rank per particle, mass per cluster, its
// smallest cell, or by contact its smallest particle), largest first.
py::tuple label(const py::object& positions, double L, const std::string& definition,
                const std::optional<py::object>& diameter_values) {
  const ClusterDefinition def = parse_cluster_definition(definition);
  const PointRows rows(positions, "positions", L);
  const Geometry g(rows.dimension());
  if (def.contact()) {
    const std::vector<double> diameter = diameters(diameter_values, rows.xyz().size() / 3);
    check_cutoff(def, L, "positions", diameter);
    ContactLabeller labeller;
    labeller.label(L, rows.xyz(), def.cutoff, g, diameter);
    RankedContacts r = contact_ranks(labeller, rows.xyz().size() / 3);
    const auto n = py::ssize_t(r.rank.size()), k = py::ssize_t(r.mass.size());
    return py::make_tuple(to_numpy(std::move(r.rank), {n}), to_numpy(std::move(r.mass), {k}),
                          to_numpy(std::move(r.first_particle), {k}), 0);
  }
  const ClusterGrid grid(L, g);
  ClusterLabeller labeller;
  labeller.label(grid, rows.xyz());
  const std::vector<Cluster> ranked = labeller.ranked();
  std::vector<std::int32_t> ranks = particle_ranks(grid, labeller, ranked, rows.xyz());
  std::vector<std::int64_t> mass, first_cell;
  for (const Cluster& c : ranked) {
    mass.push_back(c.mass);
    first_cell.push_back(c.first_cell);
  }
  const auto n = py::ssize_t(ranks.size()), k = py::ssize_t(ranked.size());
  return py::make_tuple(to_numpy(std::move(ranks), {n}), to_numpy(std::move(mass), {k}),
                        to_numpy(std::move(first_cell), {k}), grid.per_side());
}

// One frame's coolgas-clusters rows. Gas: `positions`; aggregation: `masses`
// (the aggregates are the clusters) and the slots N of the file, which size the bins.
py::dict table(const py::object& positions, double L, double t, const std::string& table, int bins_per_decade,
               const std::optional<py::object>& masses, std::optional<std::int64_t> slots, const std::string& definition,
               const std::optional<py::object>& diameter_values) {
  const ClusterDefinition def = parse_cluster_definition(definition);
  if (bins_per_decade < 1) throw InputError("bins_per_decade must be >= 1, got " + std::to_string(bins_per_decade));
  if (!std::isfinite(t)) throw InputError("t = " + format_number(t) + " is not a finite number");
  const ClusterTable kind = table_of(table);
  const PointRows rows(positions, "positions", L);
  const auto pos = rows.xyz();
  if (slots && (*slots < 1 || *slots > kMaxIndex32))
    throw InputError("slots = " + std::to_string(*slots) + " is not a particle count (1 to " +
                     std::to_string(kMaxIndex32) + ")");
  const std::int64_t n = slots ? *slots : std::int64_t(pos.size() / 3);
  if (n < 1) throw InputError("positions holds no particle; a cluster table needs at least one");
  // An aggregate holds 1 to N (the slots) particles: the histogram's bins end there.
  const std::vector<double> agg =
      masses ? coolgas::python::masses(*masses, "masses", pos.size() / 3, double(n), true) : std::vector<double>();
  if (masses && def.contact())
    throw InputError("definition " + definition_name(def) + ": aggregates (masses given) are clusters themselves");
  const std::vector<double> diameter = def.contact() ? diameters(diameter_values, pos.size() / 3) : std::vector<double>();
  check_cutoff(def, L, "positions", diameter);
  MassHistogram hist(bins_per_decade, n);
  Labellers labellers;
  fill_cluster_masses(hist, labellers, def, L, pos, agg, Geometry(rows.dimension()), diameter);
  const TableBlock b = cluster_block(kind, t, L, hist, Geometry(rows.dimension()));
  return table_dict(cluster_columns(kind), b.rows, b.comment);
}

}  // namespace

void bind_clusters(py::module_& m) {
  m.def("label_clusters", &label, py::arg("positions"), py::arg("L"), py::arg("definition") = "cells",
        py::arg("diameters") = py::none());
  m.def("cluster_table", &table, py::arg("positions"), py::arg("L"), py::arg("t"), py::arg("table"),
        py::arg("bins_per_decade"), py::arg("masses") = py::none(), py::arg("slots") = py::none(),
        py::arg("definition") = "cells", py::arg("diameters") = py::none());
}

}  // namespace coolgas::python
