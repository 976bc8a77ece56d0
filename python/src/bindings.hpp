#pragma once
// The parts of the module `shockgas._shockgas`, one file each (bind_*.cpp);
// module.cpp puts them together. The Python package (python/shockgas/) wraps
// them with signatures, docstrings and result classes.
#include <pybind11/pybind11.h>

#include <vector>

#include "shockgas/continuum/field.hpp"

namespace shockgas::python {

namespace py = pybind11;

void bind_particles(py::module_& m, py::module_& particles);  // simulate, hull
void bind_continuum(py::module_& continuum);                  // solve, the registry
void bind_compare(py::module_& compare);                      // shocks, clusters, matching
void bind_run(py::module_& m);                                // scenes: run, run_toml, load

// Shocks as columns x, mass, jump, v (bind_continuum.cpp).
py::dict shocks_dict(const std::vector<continuum::Shock>& shocks);

}  // namespace shockgas::python
