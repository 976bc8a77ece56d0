#include "keywords.hpp"

#include <pybind11/numpy.h>

#include <vector>

#include "shockgas/app/scene/scene_schema.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::python {

namespace {

// A value no reader accepts (Type::other): the key's reader refuses it, naming it.
ParameterValue unreadable(const py::handle& value) {
  ParameterValue other;
  other.written = std::string(py::str(py::repr(value)));
  return other;
}

}  // namespace

// Python and numpy scalars by their type, in this order: a numpy array is read
// as its tolist() (a list, or a 0-d array's item; it has __index__ too, so it
// must not reach the integer branch); bool before int (bool is an int in
// Python); an int beyond int64 cannot be read.
ParameterValue to_parameter(const py::handle& value) {
  if (py::isinstance<py::array>(value))  // as Python scalars and nested lists: a subclass (np.matrix)
    return to_parameter(value.attr("tolist")());  // iterates to itself, so it is not iterated
  const py::module_ numpy = py::module_::import("numpy");
  if (py::isinstance<py::bool_>(value) || py::isinstance(value, numpy.attr("bool_")))
    return ParameterValue::of(py::bool_(py::reinterpret_borrow<py::object>(value)).cast<bool>());
  if (PyLong_Check(value.ptr()) || py::isinstance(value, numpy.attr("integer"))) {
    int overflow = 0;
    const py::int_ as_int(py::reinterpret_borrow<py::object>(value));
    const long long i = PyLong_AsLongLongAndOverflow(as_int.ptr(), &overflow);
    return overflow == 0 ? ParameterValue::of(static_cast<std::int64_t>(i)) : unreadable(value);
  }
  if (PyFloat_Check(value.ptr()) || py::isinstance(value, numpy.attr("floating")))
    return ParameterValue::of(value.cast<double>());
  if (py::isinstance<py::str>(value)) return ParameterValue::of(value.cast<std::string>());
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::vector<ParameterValue> items;
    for (const py::handle item : py::iter(value)) items.push_back(to_parameter(item));
    return ParameterValue::list(std::move(items));
  }
  return unreadable(value);
}

std::size_t to_count(const py::handle& value, const std::string& key, long long min) {
  const auto n = ParameterType<std::uint64_t>::read(to_parameter(value), key, allowed(at_least(min)));
  return static_cast<std::size_t>(n);
}

void refuse_leftover(const py::dict& kwargs, const std::string& function, const std::string& accepted) {
  for (const auto& [key, value] : kwargs)
    throw InputError(std::string(py::str(key)), to_parameter(value).written,
                     "a keyword of " + function + ": " + accepted);
}

std::string keyword_doc(const ParameterInfo& info, const ParameterValue& default_value) {
  std::string line = "    " + info.key + " : " + info.kind;
  if (!info.unit.empty() && info.unit != "1") line += " [" + info.unit + "]";
  line += ", default " + app::toml_text(default_value) + "\n        " + info.doc +
          ". Allowed: " + info.allowed() + ".\n";
  return line;
}

}  // namespace shockgas::python
