#pragma once
// shockgas's errors as the Python exceptions a user expects:
//
//   InputError  -> shockgas.InputError, a ValueError with the command line's
//                  message and the attributes key, value, allowed, where;
//   RunError    -> RuntimeError;
//   Interrupted -> KeyboardInterrupt (a computation stopped on request).
#include <pybind11/pybind11.h>

namespace shockgas::python {

void register_errors(pybind11::module_& m);

}  // namespace shockgas::python
