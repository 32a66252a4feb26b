// Reading, wrapped: TSV tables (common/tsv.h), a run's parameters and
// observables (common/trajectory/run_info.h), the dumps of a coolgas
// trajectory (frame_reader.h) and the frames of another program's H5MD file
// (h5md_frame.h). Each returns plain dicts of numpy arrays; coolgas/_run.py
// and coolgas/_tables.py make the user's objects of them.
#include <variant>

#include "analyze/python/arrays.h"
#include "common/hdf5_file.h"
#include "common/trajectory/frame_reader.h"
#include "common/trajectory/h5md_frame.h"
#include "common/trajectory/layout.h"
#include "common/trajectory/run_info.h"

namespace coolgas::python {
namespace {

py::dict read_table_dict(const std::string& path) {
  Table t = read_table(path);
  py::dict d = table_dict(t.columns, t.rows);
  d["provenance"] = t.provenance;
  d["block"] = to_numpy(std::move(t.row_block), {py::ssize_t(t.rows.size())});
  d["source"] = t.source;
  return d;
}

// Every /parameters field the file holds (run_parameters.h), typed.
py::dict parameters(const std::string& path) {
  const RunParameters p = read_run_info(path).params;
  py::dict d;
  for (const ParameterField& f : run_parameter_fields()) {
    const py::str name(std::string(f.name));
    std::visit(
        [&](auto member) {
          if constexpr (std::is_same_v<decltype(member), ModelValue>) {
            const auto it = p.collision.find(f.name);
            if (it != p.collision.end()) d[name] = it->second;
          } else if constexpr (std::is_same_v<decltype(member), std::optional<double> RunParameters::*>) {
            if (p.*member) d[name] = *(p.*member);  // present only in the runs that have it (driving)
          } else if constexpr (std::is_same_v<decltype(member), std::vector<double> RunParameters::*>) {
            if (!(p.*member).empty()) d[name] = p.*member;  // a mixture's species table: a list per species
          } else {
            d[name] = p.*member;
          }
        },
        f.member);
  }
  return d;
}

py::tuple observable(const std::string& path, const std::string& name) {
  ObservableRows r = read_observable_rows(path, std::string(layout::kObservables) + "/" + name);
  const auto rows = py::ssize_t(r.time.size());
  py::array value = !r.vectors ? py::array(to_numpy(std::move(r.value), {rows}))
                                   : py::array(to_numpy(std::move(r.value), {rows, py::ssize_t(r.per_row)}));
  return py::make_tuple(to_numpy(std::move(r.time), {rows}), value);
}

bool is_coolgas_file(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  return layout::is_coolgas(f.id());
}

// A coolgas trajectory opened once; the dumps complete at that moment.
class TrajectoryView {
 public:
  explicit TrajectoryView(const std::string& path)
      : traj_(path, kPosition | kVelocity | kImage | kMass | kDiameter | kAngularVelocity | kSpecies | kAnyDimension) {}

  py::dict read(std::size_t dump) const {
    if (dump >= traj_.dump_times().size())
      throw py::index_error("dump " + std::to_string(dump) + " out of range: the file holds " +
                            std::to_string(traj_.dump_times().size()) + " complete dumps");
    Frame f;
    traj_.read(dump, f);
    const auto n = py::ssize_t(f.particles());
    const int dim = traj_.dimension();  // rows of d numbers: (n, 2) for disks, (n, 1) for rods
    py::dict d;
    d["index"] = f.dump;
    d["t"] = f.time;
    d["step"] = f.step;
    d["L"] = f.L;
    d["positions"] = rows_of(std::move(f.position), std::size_t(n), dim);
    d["velocities"] = rows_of(std::move(f.velocity), std::size_t(n), dim);
    d["images"] = rows_of(std::move(f.image), std::size_t(n), dim);
    if (!f.angular_velocity.empty()) d["angular_velocities"] = rows_of(std::move(f.angular_velocity), std::size_t(n), 3);
    if (traj_.aggregates()) d["ids"] = to_numpy(std::move(f.id), {n});
    // A mixture: each particle's species, and its mass and diameter from it.
    if (!f.species.empty()) d["species"] = to_numpy(std::move(f.species), {n});
    if (traj_.aggregates() || d.contains("species")) {
      d["masses"] = to_numpy(std::move(f.mass), {n});
      d["diameters"] = to_numpy(std::move(f.diameter), {n});
    }
    return d;
  }

  const Trajectory& trajectory() const { return traj_; }

 private:
  Trajectory traj_;
};

py::dict h5md_frame_dict(H5mdFrame f) {
  const auto n = py::ssize_t(f.position.size() / 3);
  py::dict d;
  d["index"] = f.index;
  d["frames"] = f.frames;
  d["group"] = f.group;
  d["t"] = f.time ? py::object(py::float_(*f.time)) : py::object(py::none());
  d["times"] = to_numpy(std::move(f.times), {py::ssize_t(f.times.size())});
  d["L"] = f.L;
  d["length_unit"] = f.length_unit;
  d["dimension"] = f.dimension;  // rows of d numbers, as the file holds them
  d["positions"] = rows_of(std::move(f.position), std::size_t(n), f.dimension);
  if (!f.velocity.empty()) d["velocities"] = rows_of(std::move(f.velocity), std::size_t(n), f.dimension);
  if (!f.mass.empty()) d["masses"] = to_numpy(std::move(f.mass), {n});
  if (!f.diameter.empty()) d["diameters"] = to_numpy(std::move(f.diameter), {n});
  if (!f.id.empty()) d["ids"] = to_numpy(std::move(f.id), {n});
  return d;
}

}  // namespace

void bind_reading(py::module_& m) {
  m.def("read_table", &read_table_dict, py::arg("path"), "a TSV table: columns, rows, provenance, blocks");
  m.def("parameters", &parameters, py::arg("path"), "the /parameters of a coolgas trajectory");
  m.def("observable_names", &observable_names, py::arg("path"), "the elements under /observables");
  m.def("observable", &observable, py::arg("path"), py::arg("name"),
        "one observable element up to the last complete dump: (time, value)");
  m.def("is_coolgas_file", &is_coolgas_file, py::arg("path"), "a coolgas trajectory, not another program's H5MD file");
  py::class_<TrajectoryView>(m, "Trajectory", "the complete dumps of a coolgas trajectory at the moment it is opened")
      .def(py::init<const std::string&>(), py::arg("path"))
      .def_property_readonly("times",
                             [](const TrajectoryView& v) {
                               auto t = v.trajectory().dump_times();
                               return to_numpy(std::move(t), {py::ssize_t(v.trajectory().dump_times().size())});
                             })
      .def_property_readonly("slots", [](const TrajectoryView& v) { return v.trajectory().particles(); })
      .def_property_readonly("aggregates", [](const TrajectoryView& v) { return v.trajectory().aggregates(); })
      .def_property_readonly("dimension", [](const TrajectoryView& v) { return v.trajectory().dimension(); })
      .def("nearest", [](const TrajectoryView& v, double t) { return v.trajectory().nearest_dump(t); }, py::arg("t"))
      .def("read", &TrajectoryView::read, py::arg("dump"));
  m.def("h5md_frame", [](const std::string& path, std::size_t index) { return h5md_frame_dict(read_h5md_frame_at(path, index)); },
        py::arg("path"), py::arg("index"), "frame `index` of an H5MD 1.1 file of any program");
  m.def("h5md_frame_near", [](const std::string& path, double t) { return h5md_frame_dict(read_h5md_frame(path, t)); },
        py::arg("path"), py::arg("t"), "the frame of an H5MD 1.1 file nearest time t");
}

}  // namespace coolgas::python
