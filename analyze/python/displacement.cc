// Displacements, wrapped: one dump's coolgas-displacement row from its arrays
// and the reference dump's (analyze/displacement/displacement_table.h).
#include "analyze/displacement/displacement_table.h"
#include "analyze/python/arrays.h"
#include "common/trajectory/widen_rows.h"

namespace coolgas::python {
namespace {

// Integer image counts of the positions' shape (n, d), as 3 per particle.
std::vector<std::int32_t> image_rows(const py::object& given, const char* name, std::size_t n, int d) {
  const py::array a = py::array::ensure(given);
  if (!a || (a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
    throw InputError(std::string(name) + " must be an integer array (periodic image counts)");
  const auto ints = py::cast<py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>>(a);
  if (ints.ndim() != 2 || std::size_t(ints.shape(0)) != n || ints.shape(1) != d)
    throw InputError(std::string(name) + " must have the positions' shape (" + std::to_string(n) + ", " +
                     std::to_string(d) + ")");
  std::vector<std::int32_t> v(ints.data(), ints.data() + ints.size());
  widen_to_three(v, n, std::size_t(d));
  return v;
}

struct Dump {
  Dump(const py::object& positions, const py::object& images, const py::object& velocities, double L, const char* which)
      : position(positions, (std::string(which) + " positions").c_str(), L),
        velocity(velocities, (std::string(which) + " velocities").c_str()),
        image(image_rows(images, (std::string(which) + " images").c_str(), position.xyz().size() / 3,
                         position.dimension())) {
    if (velocity.xyz().size() != position.xyz().size() || velocity.dimension() != position.dimension())
      throw InputError(std::string(which) + " velocities must have the positions' shape");
  }
  PointRows position, velocity;
  std::vector<std::int32_t> image;
};

py::dict row(const py::object& positions, const py::object& images, const py::object& velocities, double L, double t,
             const py::object& ref_positions, const py::object& ref_images, const py::object& ref_velocities,
             double L_ref, double t_ref) {
  if (!std::isfinite(t) || !std::isfinite(t_ref))
    throw InputError("t = " + format_number(t) + ", t_ref = " + format_number(t_ref) + ": give finite times");
  const Dump ref(ref_positions, ref_images, ref_velocities, L_ref, "reference");
  const Dump now(positions, images, velocities, L, "frame");
  if (now.position.dimension() != ref.position.dimension())
    throw InputError("the frame and the reference differ in dimension");
  const DisplacementOrigin origin(L_ref, ref.position.xyz(), ref.image, ref.velocity.xyz(),
                                  Geometry(ref.position.dimension()));
  const TableBlock b =
      displacement_row(origin, t_ref, L_ref, t, L, now.position.xyz(), now.image, now.velocity.xyz());
  return table_dict(displacement_columns(), b.rows, b.comment);
}

}  // namespace

void bind_displacement(py::module_& m) {
  m.def("displacement_row", &row, py::arg("positions"), py::arg("images"), py::arg("velocities"), py::arg("L"),
        py::arg("t"), py::arg("ref_positions"), py::arg("ref_images"), py::arg("ref_velocities"), py::arg("L_ref"),
        py::arg("t_ref"));
}

}  // namespace coolgas::python
