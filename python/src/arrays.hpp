#pragma once
// numpy arrays that are views of Sweep's memory, not copies: each array's base is a capsule
// holding what keeps the memory alive (a view's owner, or a vector moved into it), so the memory
// lives as long as any array (or slice of one) that shows it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <utility>
#include <vector>

namespace sweep_python {

namespace py = pybind11;

/// A capsule that owns a copy of `owner` (a shared_ptr: the view's keep-alive).
inline py::capsule keep_alive(std::shared_ptr<const void> owner) {
  auto* held = new std::shared_ptr<const void>(std::move(owner));
  return py::capsule(held, [](void* p) { delete static_cast<std::shared_ptr<const void>*>(p); });
}

/// A capsule that owns `values` (moved in: its buffer is not copied).
template <typename T>
py::capsule owning(std::vector<T>&& values) {
  auto* held = new std::vector<T>(std::move(values));
  return py::capsule(held, [](void* p) { delete static_cast<std::vector<T>*>(p); });
}

/// A read-only array of `shape` over `data` (C order unless `strides` are given), kept alive by `base`.
template <typename T>
py::array_t<T> view(const T* data, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
                    const py::capsule& base) {
  py::array_t<T> out(std::move(shape), std::move(strides), data, base);
  py::detail::array_proxy(out.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return out;
}

/// Strides of a C-ordered array of T with `shape`.
template <typename T>
std::vector<py::ssize_t> c_strides(const std::vector<py::ssize_t>& shape) {
  std::vector<py::ssize_t> strides(shape.size());
  py::ssize_t step = sizeof(T);
  for (std::size_t i = shape.size(); i-- > 0;) {
    strides[i] = step;
    step *= shape[i];
  }
  return strides;
}

}  // namespace sweep_python
