#pragma once
// Keyword arguments as scene keys: each keyword is set through the declaration
// of the scene key of the same name (shockgas/core/parameters.hpp), so it is read,
// range-checked and refused exactly as in a scene, with the same InputError
// naming the key ("particles.r = 2 is not allowed; allowed: a finite number in
// [0, 1]"). The keyword lists of the docstrings come from the same declarations.
#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>

#include "shockgas/core/parameters.hpp"

namespace shockgas::python {

namespace py = pybind11;

// A Python value as a scene value: bool, int, float, str, or a list, tuple or
// 1-D array of those. `written` is its TOML text, as a message shows it.
ParameterValue to_parameter(const py::handle& value);

// A count given as an argument (not a scene key), read as a scene's integer
// key is (whole floats too), at least `min`: InputError naming `key` for a
// bool, a fraction, a string, a negative number or one beyond int64 (pybind's
// own conversion to an unsigned count raised a bare TypeError for these).
std::size_t to_count(const py::handle& value, const std::string& key, long long min);

// Sets every keyword of `kwargs` that `table` declares, and removes it from kwargs.
template <class Params>
void take_keywords(Params& p, const ParameterTable<Params>& table, py::dict& kwargs) {
  for (const auto& e : table.entries()) {
    const py::str key(e.info.key);
    if (!kwargs.contains(key)) continue;
    e.set(p, to_parameter(kwargs[key]));
    PyDict_DelItem(kwargs.ptr(), key.ptr());
  }
}

// Throws InputError naming the first keyword left in kwargs (one no table
// took), listing those `function` accepts.
void refuse_leftover(const py::dict& kwargs, const std::string& function, const std::string& accepted);

// One docstring entry: name, kind, unit, default, meaning and what is allowed.
std::string keyword_doc(const ParameterInfo& info, const ParameterValue& default_value);

// The docstring entries of every key of `table`, defaults from `defaults`.
template <class Params>
std::string keyword_docs(const ParameterTable<Params>& table, const Params& defaults = {}) {
  std::string out;
  for (const auto& e : table.entries()) out += keyword_doc(e.info, e.get(defaults));
  return out;
}

}  // namespace shockgas::python
