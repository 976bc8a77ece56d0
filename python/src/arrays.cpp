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

ScalarKind scalar_kind(const py::handle& value) {
  const py::module_ numpy = py::module_::import("numpy");
  if (py::isinstance<py::bool_>(value) || py::isinstance(value, numpy.attr("bool_")))
    return ScalarKind::boolean;
  if (PyLong_Check(value.ptr()) || py::isinstance(value, numpy.attr("integer"))) return ScalarKind::integer;
  if (PyFloat_Check(value.ptr()) || py::isinstance(value, numpy.attr("floating"))) return ScalarKind::real;
  return ScalarKind::other;
}

bool to_int64(const py::handle& value, std::int64_t& out) {
  int overflow = 0;
  const py::int_ as_int(py::reinterpret_borrow<py::object>(value));
  out = PyLong_AsLongLongAndOverflow(as_int.ptr(), &overflow);
  return overflow == 0;
}

std::size_t to_count(const py::handle& value, const std::string& key, long long min) {
  const auto refuse = [&] {
    return InputError(key, std::string(py::str(py::repr(value))).substr(0, 80),
                      "an integer >= " + std::to_string(min));
  };
  std::int64_t count = 0;
  switch (scalar_kind(value)) {
    case ScalarKind::integer:
      if (!to_int64(value, count)) throw refuse();
      break;
    case ScalarKind::real: {  // a whole float, as the scene keys take one
      const double x = value.cast<double>();
      if (!(std::isfinite(x) && x == std::floor(x) && std::abs(x) < 9.2e18)) throw refuse();
      count = static_cast<std::int64_t>(x);
      break;
    }
    default:
      throw refuse();
  }
  if (count < min) throw refuse();
  return static_cast<std::size_t>(count);
}

}  // namespace shockgas::python
