#include "keywords.hpp"

#include <pybind11/numpy.h>

#include <vector>

#include "scene_schema.hpp"
#include "shockgas/core/error.hpp"

namespace shockgas::python {

ParameterValue to_parameter(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return ParameterValue::of(value.cast<bool>());
  if (PyLong_Check(value.ptr()) || (!PyFloat_Check(value.ptr()) && PyIndex_Check(value.ptr())))
    return ParameterValue::of(value.cast<std::int64_t>());  // int, numpy integers
  if (PyFloat_Check(value.ptr()) || py::isinstance(value, py::module_::import("numpy").attr("floating")))
    return ParameterValue::of(value.cast<double>());
  if (py::isinstance<py::str>(value)) return ParameterValue::of(value.cast<std::string>());
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value) ||
      py::isinstance<py::array>(value)) {
    std::vector<ParameterValue> items;
    for (const py::handle item : py::iter(value)) items.push_back(to_parameter(item));
    return ParameterValue::list(std::move(items));
  }
  ParameterValue other;
  other.written = std::string(py::str(py::repr(value)));
  return other;  // Type::other: every reader refuses it, naming the key
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
