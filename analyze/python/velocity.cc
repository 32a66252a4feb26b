// Velocity statistics, wrapped: Φ(y), κ and the tail fit of one frame
// (analyze/velocity/velocity_table.h), as coolgas-velocity computes them.
#include "analyze/python/arrays.h"
#include "analyze/velocity/velocity_table.h"

namespace coolgas::python {
namespace {

VelocityTable table_of(const std::string& name) {
  return choice<VelocityTable>(name,
                               {{"Phi", VelocityTable::kPhi},
                                {"tail", VelocityTable::kTail},
                                {"series", VelocityTable::kSeries}},
                               "table", "a velocity table");
}

py::dict table(const py::object& velocities, double t, const std::string& table, int bins, double ymax, double tail_from,
               double min_count) {
  const VelocityTable kind = table_of(table);
  if (!std::isfinite(t)) throw InputError("t = " + format_number(t) + " is not a finite number");
  const PointRows v(velocities, "velocities");
  check_tail_options(tail_from, min_count);
  ComponentHistogram hist(bins, ymax);
  const VelocityStats s = velocity_stats(v.xyz(), hist, tail_from, min_count, Geometry(v.dimension()));
  if (kind == VelocityTable::kTail && !s.fit)
    throw InputError("only " + std::to_string(s.tail.size()) + " tail bins with y >= " + format_number(tail_from) +
                     " and >= " + format_number(min_count) +
                     " samples (3 needed to fit beta); lower tail_from or min_count, or use wider bins");
  const TableBlock b = velocity_block(kind, t, hist, s, tail_from);
  py::dict d = table_dict(velocity_columns(kind), b.rows, b.comment);
  d["v_rms"] = s.moments.v_rms;
  d["kappa"] = s.moments.kappa;
  d["kappa_err"] = s.moments.kappa_err;
  d["beta"] = s.fit ? py::object(py::float_(s.fit->beta)) : py::object(py::none());
  d["beta_err"] = s.fit ? py::object(py::float_(s.fit->beta_err)) : py::object(py::none());
  d["tail_points"] = s.fit ? s.fit->points : int(s.tail.size());
  return d;
}

}  // namespace

void bind_velocity(py::module_& m) {
  m.def("velocity_table", &table, py::arg("velocities"), py::arg("t"), py::arg("table"), py::arg("bins"),
        py::arg("ymax"), py::arg("tail_from"), py::arg("min_count"));
}

}  // namespace coolgas::python
