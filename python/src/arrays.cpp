#include "arrays.hpp"

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

}  // namespace shockgas::python
