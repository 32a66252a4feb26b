// Structure, wrapped: S(k), L_t, the correlation lengths and g(r) of one
// frame (analyze/structure/structure_table.h), as coolgas-structure computes them.
#include "analyze/python/arrays.h"
#include "common/limits.h"
#include "common/memory.h"
#include "analyze/structure/structure_table.h"

namespace coolgas::python {
namespace {

StructureTable table_of(const std::string& name) {
  return choice<StructureTable>(name,
                                {{"spectrum", StructureTable::kSpectrum},
                                 {"series", StructureTable::kSeries},
                                 {"correlation", StructureTable::kCorrelation},
                                 {"rdf", StructureTable::kRdf},
                                 {"rdf_series", StructureTable::kRdfSeries}},
                                "table", "a structure table");
}

// g(r) or its contact value (--rdf, --rdf --series) of unit particles.
py::dict rdf_table(StructureTable kind, const PointRows& rows, double L, double t, bool has_masses, double r_max,
                   int bins_per_sigma, int contact_bins) {
  check_rdf_options(r_max, bins_per_sigma, contact_bins);
  if (has_masses) throw InputError("g(r) is for particles of one diameter: give no masses with an rdf table");
  const double range = rdf_range(r_max, L, bins_per_sigma, contact_bins);
  const Geometry g(rows.dimension());
  PairDistances pairs(g, range, bins_per_sigma);
  const TableBlock b = rdf_block(kind, pairs, t, L, rows.xyz(), contact_bins, g);
  py::dict d = table_dict(structure_columns(kind), b.rows, b.comment);
  d["r_max"] = pairs.r_max();
  return d;
}

py::dict table(const py::object& positions, double L, double t, const std::string& table,
               const std::optional<py::object>& velocities, const std::optional<py::object>& masses, int grid,
               double peak_fraction, int direct_shells, double r_max, int bins_per_sigma, int contact_bins) {
  const StructureTable kind = table_of(table);
  check_structure_options(grid, peak_fraction, direct_shells);
  if (!std::isfinite(t)) throw InputError("t = " + format_number(t) + " is not a finite number");
  const PointRows rows(positions, "positions", L);
  if (is_rdf(kind)) return rdf_table(kind, rows, L, t, masses.has_value(), r_max, bins_per_sigma, contact_bins);
  const auto pos = rows.xyz();
  const std::size_t n = pos.size() / 3;
  if (n == 0) throw InputError("positions holds no particle; S(k) needs at least one");
  const std::optional<PointRows> vel_rows =
      velocities ? std::optional<PointRows>(std::in_place, *velocities, "velocities") : std::nullopt;
  const auto vel = vel_rows ? vel_rows->xyz() : std::span<const double>();
  const bool vel_fits = vel_rows && vel.size() == pos.size() && vel_rows->dimension() == rows.dimension();
  if (kind != StructureTable::kSpectrum && !vel_fits)
    throw InputError("the " + table + " table needs velocities of the positions' shape (" + std::to_string(n) + ", " +
                     std::to_string(rows.dimension()) + "), got " +
                     (vel_rows ? "(" + std::to_string(vel.size() / 3) + ", " + std::to_string(vel_rows->dimension()) + ")"
                               : std::string("none")));
  // Weights of the density: > 0, at most what a file's aggregate holds.
  const std::vector<double> w =
      masses ? coolgas::python::masses(*masses, "masses", n, double(kMaxIndex32), false) : std::vector<double>();
  const int points = structure_grid_points(grid, L, Geometry(rows.dimension()), usable_memory_bytes());
  FrameStructure fs(points, Geometry(rows.dimension()));
  const TableBlock b = structure_block(kind, fs, t, L, pos, vel, w, peak_fraction, direct_shells);
  py::dict d = table_dict(structure_columns(kind), b.rows, b.comment);
  d["grid"] = points;
  return d;
}

}  // namespace

void bind_structure(py::module_& m) {
  const StructureOptions d;  // the tool's defaults
  m.def("structure_table", &table, py::arg("positions"), py::arg("L"), py::arg("t"), py::arg("table"),
        py::arg("velocities") = py::none(), py::arg("masses") = py::none(), py::arg("grid") = d.grid,
        py::arg("peak_fraction") = d.peak_fraction, py::arg("direct_shells") = d.direct_shells,
        py::arg("r_max") = d.r_max, py::arg("bins_per_sigma") = d.bins_per_sigma, py::arg("contact_bins") = d.contact_bins);
}

}  // namespace coolgas::python
