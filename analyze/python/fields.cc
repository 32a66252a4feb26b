// Fields, wrapped: one frame's coolgas-fields table (analyze/fields/fields_table.h),
// as the tool computes it.
#include "analyze/fields/fields_table.h"
#include "analyze/fields/tool.h"
#include "analyze/python/arrays.h"
#include "common/limits.h"
#include "common/memory.h"

namespace coolgas::python {
namespace {

FieldsTable table_of(const std::string& name) {
  return choice<FieldsTable>(name,
                             {{"series", FieldsTable::kSeries},
                              {"spectrum", FieldsTable::kSpectrum},
                              {"slab", FieldsTable::kSlab}},
                             "table", "a fields table");
}

py::dict table(const py::object& positions, const py::object& velocities, double L, double t, const std::string& table,
               const std::optional<py::object>& masses, double cell) {
  const FieldsTable kind = table_of(table);
  if (!std::isfinite(t)) throw InputError("t = " + format_number(t) + " is not a finite number");
  const PointRows rows(positions, "positions", L);
  const PointRows vel_rows(velocities, "velocities");
  const auto pos = rows.xyz(), vel = vel_rows.xyz();
  const std::size_t n = pos.size() / 3;
  if (n < 2) throw InputError("positions holds " + std::to_string(n) + " particles; the fields need at least 2");
  if (vel.size() != pos.size() || vel_rows.dimension() != rows.dimension())
    throw InputError("velocities must have the positions' shape (" + std::to_string(n) + ", " +
                     std::to_string(rows.dimension()) + "), got (" + std::to_string(vel.size() / 3) + ", " +
                     std::to_string(vel_rows.dimension()) + ")");
  const Geometry g(rows.dimension());
  if (kind == FieldsTable::kSlab && g.d() == 1) throw InputError("table \"slab\" draws a plane of cells; rods have none");
  const std::vector<double> w =
      masses ? coolgas::python::masses(*masses, "masses", n, double(kMaxIndex32), false) : std::vector<double>();
  FourierGrid grid(field_cells(L, cell, g, usable_memory_bytes()), g);
  const TableBlock b = fields_block(kind, grid, t, L, pos, vel, w);
  py::dict d = table_dict(fields_columns(kind), b.rows, b.comment);
  d["cells"] = grid.n();
  return d;
}

}  // namespace

void bind_fields(py::module_& m) {
  const FieldsOptions d;  // the tool's defaults
  m.def("fields_table", &table, py::arg("positions"), py::arg("velocities"), py::arg("L"), py::arg("t"),
        py::arg("table"), py::arg("masses") = py::none(), py::arg("cell") = d.cell);
}

}  // namespace coolgas::python
