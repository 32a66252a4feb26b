// Structure, wrapped: S(k), L_t and the correlation lengths of one frame
// (analyze/structure/structure_table.h), as coolgas-structure computes them.
#include "analyze/python/arrays.h"
#include "analyze/structure/structure_table.h"

namespace coolgas::python {
namespace {

StructureTable table_of(const std::string& name) {
  return choice<StructureTable>(name,
                                {{"spectrum", StructureTable::kSpectrum},
                                 {"series", StructureTable::kSeries},
                                 {"correlation", StructureTable::kCorrelation}},
                                "table", "a structure table");
}

py::dict table(const Doubles& positions, double L, double t, const std::string& table,
               const std::optional<Doubles>& velocities, const std::optional<Doubles>& masses, int grid,
               double peak_fraction, int direct_shells) {
  const StructureTable kind = table_of(table);
  check_structure_options(grid, peak_fraction, direct_shells);
  if (!(L > 0 && std::isfinite(L))) throw InputError("L = " + format_number(L) + " is not a box side (a number > 0)");
  const PointRows rows(positions, "positions");
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
  const auto w = masses ? values(*masses, "masses") : std::span<const double>();
  if (masses && w.size() != n)
    throw InputError("masses holds " + std::to_string(w.size()) + " values for " + std::to_string(n) + " positions");
  for (std::size_t i = 0; i < w.size(); ++i)
    if (!(w[i] > 0)) throw InputError("masses[" + std::to_string(i) + "] = " + format_number(w[i]) + " is not > 0");
  const int points = structure_grid_points(grid, L);
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
        py::arg("peak_fraction") = d.peak_fraction, py::arg("direct_shells") = d.direct_shells);
}

}  // namespace coolgas::python
