// NumPy arrays in and out. Results are handed to NumPy without a copy: the array owns the
// std::vector the library filled, through a capsule that deletes it.
#include <fmt/format.h>

#include "bindings.h"

namespace subdivkit {
namespace {

template <class T, class Allocator>
py::array_t<T> adopt_vector(std::vector<T, Allocator>&& values, std::vector<py::ssize_t> shape) {
  using Vector = std::vector<T, Allocator>;
  auto* owned = new Vector(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<Vector*>(p); });
  return py::array_t<T>(shape, owned->data(), owner);
}

template <class T>
std::vector<T> vector_from(py::handle array, const std::string& what, const char* type) {
  if (array.is_none()) return {};
  auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!a) {
    PyErr_Clear();
    throw subdiv::Error(fmt::format("{}: cannot be read as an array of {}", what, type));
  }
  return std::vector<T>(a.data(), a.data() + a.size());
}

}  // namespace

py::array_t<double> adopt(std::vector<double>&& values, std::vector<py::ssize_t> shape) {
  return adopt_vector(std::move(values), std::move(shape));
}
py::array_t<std::int32_t> adopt(std::vector<std::int32_t>&& values, std::vector<py::ssize_t> shape) {
  return adopt_vector(std::move(values), std::move(shape));
}
py::array_t<std::int32_t> adopt(subdiv::ScratchVector<std::int32_t>&& values, std::vector<py::ssize_t> shape) {
  return adopt_vector(std::move(values), std::move(shape));
}
py::array_t<std::uint8_t> adopt(std::vector<std::uint8_t>&& values, std::vector<py::ssize_t> shape) {
  return adopt_vector(std::move(values), std::move(shape));
}

std::vector<double> doubles_from(py::handle array, const std::string& what) {
  return vector_from<double>(array, what, "float64");
}
std::vector<Index> indices_from(py::handle array, const std::string& what) {
  return vector_from<Index>(array, what, "int32 indices");
}

}  // namespace subdivkit
