#include "errors.hpp"

#include "shockgas/core/error.hpp"
#include "shockgas/core/interrupt.hpp"

namespace shockgas::python {

namespace py = pybind11;

void register_errors(py::module_& m) {
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Input that shockgas does not allow (a ValueError). The message is the command line's: "
      "'key = value is not allowed; allowed: ...'. Attributes: key (the scene key or keyword, "
      "e.g. 'particles.r'), value (as written), allowed, where (file:line, or '' for a keyword).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(input_error.ptr())(e.what());
      error.attr("key") = e.key();
      error.attr("value") = e.value();
      error.attr("allowed") = e.allowed();
      error.attr("where") = e.where();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    } catch (const RunError& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    } catch (const Interrupted& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });
}

}  // namespace shockgas::python
