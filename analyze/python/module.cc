// The Python module coolgas._core: the libraries' readers and kernels over
// numpy arrays. The package coolgas/ (pure Python beside this file) builds
// the user's API (open, read_table, simulate, DataFrames) on it.
#include "analyze/python/arrays.h"
#include "common/error.h"
#include "common/version.h"

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  m.doc() = "coolgas C++ libraries (readers and analysis kernels); use the package coolgas";
  // InputError (the tools' exit code 2) becomes coolgas.InputError, a
  // ValueError, with the one-line message the tool prints after "error: ".
  static py::exception<coolgas::InputError> input_error(m, "InputError", PyExc_ValueError);
  // By value: pybind11 takes a plain function of std::exception_ptr.
  py::register_exception_translator([](std::exception_ptr p) {  // NOLINT(performance-unnecessary-value-param)
    try {
      if (p) std::rethrow_exception(p);
    } catch (const coolgas::InputError& e) {
      PyErr_SetString(input_error.ptr(), coolgas::one_line(e.what()).c_str());
    }
  });
  m.def("program_version", &coolgas::program_version, "the version the tools print with --version");
  coolgas::python::bind_reading(m);
  coolgas::python::bind_clusters(m);
  coolgas::python::bind_velocity(m);
  coolgas::python::bind_structure(m);
  coolgas::python::bind_fields(m);
  coolgas::python::bind_shape(m);
  coolgas::python::bind_collapse(m);
  coolgas::python::bind_smoluchowski(m);
  coolgas::python::bind_displacement(m);
}
