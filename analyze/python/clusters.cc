// Clusters, wrapped: the paper's unit-cell labelling (analyze/labelling/) and
// the coolgas-clusters table of one frame (analyze/clusters/cluster_table.h).
#include "analyze/clusters/cluster_table.h"
#include "analyze/labelling/particle_labels.h"
#include "analyze/python/arrays.h"

namespace coolgas::python {
namespace {

ClusterTable table_of(const std::string& name) {
  return choice<ClusterTable>(name,
                              {{"distribution", ClusterTable::kDistribution},
                               {"scaled", ClusterTable::kScaled},
                               {"series", ClusterTable::kSeries}},
                              "table", "a cluster table");
}

// Labels and the size table: (rank per particle, mass per cluster, smallest cell per cluster), largest first.
py::tuple label(const Doubles& positions, double L) {
  const PointRows rows(positions, "positions");
  const ClusterGrid grid(L, Geometry(rows.dimension()));
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
py::dict table(const Doubles& positions, double L, double t, const std::string& table, int bins_per_decade,
               const std::optional<Doubles>& masses, std::int64_t slots) {
  if (bins_per_decade < 1) throw InputError("bins_per_decade must be >= 1, got " + std::to_string(bins_per_decade));
  const ClusterTable kind = table_of(table);
  const PointRows rows(positions, "positions");
  const auto pos = rows.xyz();
  const auto agg = masses ? values(*masses, "masses") : std::span<const double>();
  const std::int64_t n = slots > 0 ? slots : std::int64_t(pos.size() / 3);
  if (n < 1) throw InputError("positions holds no particle; a cluster table needs at least one");
  MassHistogram hist(bins_per_decade, n);
  ClusterLabeller labeller;
  fill_cluster_masses(hist, labeller, L, pos, agg, Geometry(rows.dimension()));
  const TableBlock b = cluster_block(kind, t, L, hist, Geometry(rows.dimension()));
  return table_dict(cluster_columns(kind), b.rows, b.comment);
}

}  // namespace

void bind_clusters(py::module_& m) {
  m.def("label_clusters", &label, py::arg("positions"), py::arg("L"));
  m.def("cluster_table", &table, py::arg("positions"), py::arg("L"), py::arg("t"), py::arg("table"),
        py::arg("bins_per_decade"), py::arg("masses") = py::none(), py::arg("slots") = 0);
}

}  // namespace coolgas::python
