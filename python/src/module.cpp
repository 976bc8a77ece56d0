// The compiled part of the Python package `shockgas` (python/shockgas/).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "errors.hpp"
#include "shockgas/version.hpp"

PYBIND11_MODULE(_shockgas, m) {
  namespace py = pybind11;
  m.doc() = "shockgas's C++ core; use the package `shockgas`, which wraps it.";
  m.attr("__version__") = shockgas::kVersion;
  m.attr("git_commit") = shockgas::kGitCommit;
  shockgas::python::register_errors(m);
  py::module_ particles = m.def_submodule("particles");
  py::module_ continuum = m.def_submodule("continuum");
  py::module_ compare = m.def_submodule("compare");
  shockgas::python::bind_particles(m, particles);
  shockgas::python::bind_continuum(continuum);
  shockgas::python::bind_compare(compare);
  shockgas::python::bind_run(m);
}
