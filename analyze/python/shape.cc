// Shapes, wrapped: every cluster's gyration tensor (eigenvalues, R_g,
// asphericity, prolateness) and the mass-radius d_f of one frame
// (analyze/shape/shape_table.h), as coolgas-shape computes them.
#include "analyze/python/arrays.h"
#include "common/limits.h"
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
py::dict table(const py::object& positions, double L, double t, const std::string& table, int bins_per_decade,
               const std::string& fit_mass, std::int64_t min_mass, const std::optional<py::object>& masses) {
  const ShapeTable kind = table_of(table);
  check_shape_options(bins_per_decade, min_mass);
  const Window fit = parse_window(fit_mass, "fit_mass");
  if (!std::isfinite(t)) throw InputError("t = " + format_number(t) + " is not a finite number");
  const PointRows rows(positions, "positions", L);
  const auto pos = rows.xyz();
  const int d = rows.dimension();
  // Aggregates (positions unused): each 1 to 2^31 - 1 particles, as a file holds.
  const std::vector<double> agg =
      masses ? coolgas::python::masses(*masses, "masses", 0, double(kMaxIndex32), true) : std::vector<double>();
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
