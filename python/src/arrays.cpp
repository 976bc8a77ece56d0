#include "arrays.hpp"

#include <cmath>

#include "shockgas/core/error.hpp"

namespace shockgas::python {

std::vector<double> to_vector(const py::handle& values, const std::string& key) {
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  Array a;
  try {
    a = Array::ensure(values);
  } catch (const py::error_already_set&) {
  }
  if (!a)
    throw InputError(key, std::string(py::str(py::repr(values))).substr(0, 80), "a 1-D array of numbers");
  if (a.ndim() != 1)
    throw InputError(key, "an array of " + std::to_string(a.ndim()) + " dimensions",
                     "a 1-D array of numbers");
  const double* data = a.data();
  return std::vector<double>(data, data + a.size());
}

std::size_t to_count(const py::handle& value, const std::string& key, long long min) {
  const std::string allowed = "an integer >= " + std::to_string(min);
  const py::module_ numpy = py::module_::import("numpy");
  const auto refuse = [&] {
    return InputError(key, std::string(py::str(py::repr(value))).substr(0, 80), allowed);
  };
  if (py::isinstance<py::bool_>(value) || py::isinstance(value, numpy.attr("bool_"))) throw refuse();
  long long count = 0;
  if (PyLong_Check(value.ptr()) || py::isinstance(value, numpy.attr("integer"))) {
    int overflow = 0;
    const py::int_ as_int(py::reinterpret_borrow<py::object>(value));
    count = PyLong_AsLongLongAndOverflow(as_int.ptr(), &overflow);
    if (overflow != 0) throw refuse();
  } else if (PyFloat_Check(value.ptr()) || py::isinstance(value, numpy.attr("floating"))) {
    const double x = value.cast<double>();
    if (!(std::isfinite(x) && x == std::floor(x) && std::abs(x) < 9.2e18)) throw refuse();
    count = static_cast<long long>(x);
  } else {
    throw refuse();
  }
  if (count < min) throw refuse();
  return static_cast<std::size_t>(count);
}

}  // namespace shockgas::python
