#include <fmt/format.h>

#include "bindings.h"

namespace subdivkit {

void refuse_bare_new(py::handle cls, const std::string& how) {
  const std::string name = py::str(cls.attr("__name__"));
  const std::string message = fmt::format("subdivkit.{} objects are not made with {}(...) or __new__: {}", name, name, how);
  // A builtin function, not a method: Python calls it as __new__(cls, *args, **kwargs).
  cls.attr("__new__") = py::cpp_function([message](const py::args&, const py::kwargs&) -> py::object {
    throw py::type_error(message);
  });
}

}  // namespace subdivkit
