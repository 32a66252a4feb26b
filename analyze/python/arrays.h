// Moving C++ results into numpy arrays and checking numpy arguments, shared
// by the binding files of the Python module. Nothing here computes physics:
// the bindings only wrap the libraries (ARCHITECTURE.md, "analyze/python/").
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <initializer_list>
#include <optional>
#include <utility>
#include <span>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/trajectory/widen_rows.h"
#include "common/tsv.h"

namespace coolgas::python {

namespace py = pybind11;

// A C-contiguous float64 array, converted from any numeric array or list.
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// `v` as a numpy array of `shape`, without a copy: the array owns the vector.
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& v, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(v));
  py::capsule free_it(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), free_it);
}

// The box side of a kernel: finite and > 0. InputError otherwise.
inline double box_side(double L) {
  if (!(std::isfinite(L) && L > 0)) throw InputError("L = " + format_number(L) + " is not a box side (a finite number > 0)");
  return L;
}

// A numeric argument as C-contiguous float64. Integers and floats are
// converted; complex numbers (whose imaginary part would be dropped),
// booleans, strings and objects are refused: InputError naming the argument
// and its dtype. The one gate every array a kernel takes passes.
inline Doubles real_numbers(const py::object& given, const std::string& name) {
  if (py::isinstance<py::str>(given) || py::isinstance<py::bytes>(given))
    throw py::type_error(name + " must be an array of numbers, got a string");
  const py::array a = py::array::ensure(given);
  if (!a) {
    PyErr_Clear();
    throw py::type_error(name + " must be an array of numbers, got " + std::string(py::str(py::type::of(given))));
  }
  const char kind = a.dtype().kind();
  if (kind == 'c')
    throw InputError(name + " is complex (dtype " + std::string(py::str(a.dtype())) +
                     "); give real numbers (its imaginary part would be dropped)");
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw InputError(name + " has dtype " + shown(std::string(py::str(a.dtype()))) +
                     "; give real numbers (integers are converted to float64)");
  return py::cast<Doubles>(a);
}

// An (N, 3) array of finite numbers (positions, velocities) as x0 y0 z0 x1 ...,
// or, for disks, an (N, 2) array as the same 3-vectors with z = 0, for rods
// an (N, 1) array with y = z = 0 (a copy: the libraries take 3 numbers per
// particle); InputError naming the argument, its shape or the first bad value.
// Positions given with their box side L must lie in [0, L): a value outside
// (or an L smaller than the data) is refused, naming both.
class PointRows {
 public:
  PointRows(const PointRows&) = delete;  // xyz() may point into the object itself
  PointRows& operator=(const PointRows&) = delete;
  PointRows(const py::object& given, const char* name, std::optional<double> L = std::nullopt)
      : array_(real_numbers(given, name)) {
    const Doubles& a = array_;
    if (a.ndim() != 2 || a.shape(1) < 1 || a.shape(1) > 3)
      throw InputError(std::string(name) + " must be an array of shape (N, 3), or (N, 2) for disks, (N, 1) for rods, got " +
                       std::to_string(a.ndim()) + " dimensions" +
                       (a.ndim() == 2 ? " (N, " + std::to_string(a.shape(1)) + ")" : ""));
    dimension_ = int(a.shape(1));
    if (L) box_side(*L);
    const std::span<const double> s(a.data(), std::size_t(a.size()));
    for (std::size_t i = 0; i < s.size(); ++i) {
      const std::string at = std::string(name) + "[" + std::to_string(i / std::size_t(dimension_)) + ", " +
                             std::to_string(i % std::size_t(dimension_)) + "] = " + format_number(s[i]);
      if (!std::isfinite(s[i])) throw InputError(at + " is not a finite number");
      if (L && !(s[i] >= 0 && s[i] < *L))
        throw InputError(at + " is outside the box [0, L) of side L = " + format_number(*L) +
                         " (wrap positions into the box, or give the box they were wrapped into)");
    }
    if (dimension_ == 3) {
      xyz_ = s;
      return;
    }
    widened_.assign(s.begin(), s.end());
    widen_to_three(widened_, s.size() / std::size_t(dimension_), std::size_t(dimension_));
    xyz_ = widened_;
  }
  std::span<const double> xyz() const { return xyz_; }
  int dimension() const { return dimension_; }

 private:
  Doubles array_;  // the float64 array xyz() may point into
  int dimension_ = 3;
  std::vector<double> widened_;  // 2D and 1D only
  std::span<const double> xyz_;
};

// The rows of a 3-wide frame array (n rows) as an (n, d) numpy array: a 2D
// file's frames hold z = 0, a 1D file's y = z = 0
// (common/trajectory/widen_rows.h), dropped here.
template <class T>
py::array_t<T> rows_of(std::vector<T>&& v, std::size_t n, int d) {
  for (std::size_t i = 0; d < 3 && i < n; ++i)
    for (int k = 0; k < d; ++k) v[i * std::size_t(d) + std::size_t(k)] = v[3 * i + std::size_t(k)];
  v.resize(n * std::size_t(d));
  return to_numpy(std::move(v), {py::ssize_t(n), py::ssize_t(d)});
}

// A 1-D array of finite numbers (masses, times, energies), copied.
inline std::vector<double> values(const py::object& given, const char* name) {
  const Doubles a = real_numbers(given, name);
  if (a.ndim() != 1)
    throw InputError(std::string(name) + " must be a 1-D array, got " + std::to_string(a.ndim()) + " dimensions");
  std::vector<double> s(a.data(), a.data() + a.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!std::isfinite(s[i]))
      throw InputError(std::string(name) + "[" + std::to_string(i) + "] = " + format_number(s[i]) +
                       " is not a finite number");
  return s;
}

// Masses: values() of `expected` entries (one per position; 0: any
// number), each > 0 and at most `most`; `particles`: counted in particles,
// so at least 1. InputError naming the first that is not (a mass of 1e300
// would index far beyond the tables the kernels fill).
inline std::vector<double> masses(const py::object& given, const char* name, std::size_t expected, double most,
                                  bool particles) {
  std::vector<double> m = values(given, name);
  if (expected > 0 && m.size() != expected)
    throw InputError(std::string(name) + " holds " + std::to_string(m.size()) + " values for " +
                     std::to_string(expected) + " positions; give one per position");
  for (std::size_t i = 0; i < m.size(); ++i)
    if (!((particles ? m[i] >= 1 : m[i] > 0) && m[i] <= most))
      throw InputError(std::string(name) + "[" + std::to_string(i) + "] = " + format_number(m[i]) + " is not a mass " +
                       (particles ? "of 1 to " + format_number(most) + " particles" : "> 0 and <= " + format_number(most)));
  return m;
}

// The value named `name` among `choices`; InputError "<what> = '<name>' is
// not a <kind>; allowed: a, b, c" otherwise.
template <class E>
E choice(const std::string& name, std::initializer_list<std::pair<const char*, E>> choices, const char* what,
         const char* kind) {
  std::string allowed;
  for (const auto& [n, value] : choices) {
    if (name == n) return value;
    allowed += (allowed.empty() ? "" : ", ") + std::string(n);
  }
  throw InputError(std::string(what) + " = '" + shown(name) + "' is not " + kind + "; allowed: " + allowed);
}

// A table's rows as a dict {"columns", "rows" (a 2-D array), "comment"}, which
// coolgas/_tables.py turns into a pandas DataFrame.
inline py::dict table_dict(const std::vector<std::string>& columns, const std::vector<std::vector<double>>& rows,
                           const std::string& comment = "") {
  std::vector<double> flat;
  flat.reserve(rows.size() * columns.size());
  for (const auto& r : rows) flat.insert(flat.end(), r.begin(), r.end());
  py::dict d;
  d["columns"] = columns;
  d["rows"] = to_numpy(std::move(flat), {py::ssize_t(rows.size()), py::ssize_t(columns.size())});
  d["comment"] = comment;
  return d;
}

// A table as common/tsv.h reads it, from `columns` and a 2-D array of rows
// (one block): what a tool given a TSV file works on. InputError, as
// read_table's, for a wrong shape or a value that is not a finite number.
inline Table table_of(const std::vector<std::string>& columns, const Doubles& rows, const std::string& source,
                      Provenance provenance = {}) {
  if (rows.ndim() != 2 || rows.shape(1) != py::ssize_t(columns.size()))
    throw InputError(source + ": rows must be an array of shape (n, " + std::to_string(columns.size()) +
                     ") for the columns given, got " + std::to_string(rows.ndim()) + " dimensions" +
                     (rows.ndim() == 2 ? " (n, " + std::to_string(rows.shape(1)) + ")" : ""));
  Table t;
  t.source = source;
  t.provenance = std::move(provenance);
  t.columns = columns;
  const auto* v = rows.data();
  for (py::ssize_t r = 0; r < rows.shape(0); ++r) {
    t.rows.emplace_back(v + r * rows.shape(1), v + (r + 1) * rows.shape(1));
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (!std::isfinite(t.rows.back()[c]))
        throw InputError(source + ": " + columns[c] + " = " + format_number(t.rows.back()[c]) + " in row " +
                         std::to_string(r + 1) + " is not a finite number");
    t.row_block.push_back(0);
  }
  if (t.rows.empty()) throw InputError(source + ": empty table (no data rows)");
  return t;
}

// The module's parts, one per binding file.
void bind_reading(py::module_& m);
void bind_clusters(py::module_& m);
void bind_velocity(py::module_& m);
void bind_structure(py::module_& m);
void bind_fields(py::module_& m);
void bind_shape(py::module_& m);
void bind_collapse(py::module_& m);
void bind_smoluchowski(py::module_& m);
void bind_displacement(py::module_& m);

}  // namespace coolgas::python
