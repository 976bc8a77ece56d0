#pragma once
// numpy arrays in and out. An input is copied once, into the vector the library
// owns (the engine changes its state); a result vector is moved into a capsule
// that the numpy array keeps alive, so its data are never copied again.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace shockgas::python {

namespace py = pybind11;

// A 1-D array-like of numbers as float64, copied once (no further copy when it
// already is a contiguous float64 array). InputError naming `key` otherwise.
std::vector<double> to_vector(const py::handle& values, const std::string& key);

// The vector's storage as a numpy array of shape {size} or {rows, cols}: no copy.
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values, std::vector<py::ssize_t> shape = {}) {
  auto owner = std::make_unique<std::vector<T>>(std::move(values));
  if (shape.empty()) shape = {static_cast<py::ssize_t>(owner->size())};
  T* data = owner->data();
  py::capsule keep(owner.get(), [](void* p) { delete static_cast<std::vector<T>*>(p); });
  static_cast<void>(owner.release());  // the capsule owns it now
  return py::array_t<T>(shape, data, keep);
}

// One field of each item, as an array of the field's type ("x of every shock").
template <class Item, class F>
auto column(const std::vector<Item>& items, F&& field) {
  using T = std::decay_t<decltype(field(items.front()))>;
  std::vector<T> out;
  out.reserve(items.size());
  for (const Item& item : items) out.push_back(field(item));
  return to_numpy(std::move(out));
}

}  // namespace shockgas::python
