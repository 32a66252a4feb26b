// Shapes, wrapped: every cluster's gyration tensor (eigenvalues, R_g,
// asphericity, prolateness) and the mass-radius d_f of one frame
// (analyze/shape/shape_table.h), as coolgas-shape computes them.
#include "analyze/python/arrays.h"
#include "analyze/shape/shape_table.h"

namespace coolgas::python {
namespace {

ShapeTable table_of(const std::string& name) {
  return choice<ShapeTable>(name,
                            {{"mass_radius", ShapeTable::kMassRadius},
                             {"series", ShapeTable::kSeries},
                             {"clusters", ShapeTable::kClusters}},
                            "table", "a shape table");
}

// Gas: the paper's clusters of `positions`; aggregation: `masses` (the
// aggregates, solid spheres; positions unused).
py::dict table(const Doubles& positions, double L, double t, const std::string& table, int bins_per_decade,
               const std::string& fit_mass, std::int64_t min_mass, const std::optional<Doubles>& masses) {
  const ShapeTable kind = table_of(table);
  check_shape_options(bins_per_decade, min_mass);
  const Window fit = parse_window(fit_mass, "fit_mass");
  const PointRows rows(positions, "positions");
  const auto pos = rows.xyz();
  const int d = rows.dimension();
  const auto agg = masses ? values(*masses, "masses") : std::span<const double>();
  for (std::size_t i = 0; i < agg.size(); ++i)
    if (!(agg[i] >= 1))
      throw InputError("masses[" + std::to_string(i) + "] = " + format_number(agg[i]) + " is not a mass >= 1 particle");
  if (pos.empty() && agg.empty()) throw InputError("positions holds no particle; a shape table needs at least one");
  ClusterShapes shapes;
  const std::vector<ClusterShape> s = masses ? aggregate_shapes(agg, Geometry(d)) : shapes.of_particles(ClusterGrid(L, Geometry(d)), pos);
  const TableBlock b = shape_block(kind, t, s, mass_radius(s, bins_per_decade, fit), min_mass, Geometry(d));
  return table_dict(shape_columns(kind, Geometry(d)), b.rows, b.comment);
}

}  // namespace

void bind_shape(py::module_& m) {
  const ShapeOptions d;  // the tool's defaults
  m.def("shape_table", &table, py::arg("positions"), py::arg("L"), py::arg("t"), py::arg("table"),
        py::arg("bins_per_decade") = d.bins_per_decade, py::arg("fit_mass") = d.fit_mass,
        py::arg("min_mass") = d.min_mass, py::arg("masses") = py::none());
}

}  // namespace coolgas::python
