// subdivkit.Scheme and subdivkit.schemes().
#include <fmt/format.h>

#include "bindings.h"
#include "framework/util/quoted_text.h"

namespace subdivkit {
namespace {

py::dict parameter_info(const subdiv::ParameterSpec& p) {
  py::dict d;
  d["name"] = p.name;
  d["description"] = p.description;
  if (p.is_choice) {
    d["value"] = p.choice;
    d["choices"] = p.choices;
  } else {
    d["value"] = p.value;
    d["minimum"] = p.has_minimum ? py::object(py::float_(p.minimum)) : py::object(py::none());
    d["maximum"] = p.has_maximum ? py::object(py::float_(p.maximum)) : py::object(py::none());
    d["minimum_exclusive"] = p.minimum_exclusive;
    d["maximum_exclusive"] = p.maximum_exclusive;
    d["per_vertex"] = p.per_vertex;
  }
  return d;
}

const std::vector<subdiv::ParameterSpec>& specs_of(const SchemeHandle& h) {
  return h.kind == "curve" ? h.curve->parameter_specs : h.surface->parameters;
}

std::string text_from_dict(const py::dict& d) {
  try {
    return py::str(py::module_::import("json").attr("dumps")(d));
  } catch (py::error_already_set& e) {
    throw subdiv::Error(fmt::format("Scheme.from_dict: the dict cannot be written as JSON: {}", e.what()));
  }
}

}  // namespace

void bind_schemes(py::module_& m) {
  auto scheme = py::class_<SchemeHandle, std::shared_ptr<SchemeHandle>>(m, "Scheme", R"doc(
A subdivision scheme: a surface scheme (refines polygon meshes) or a curve scheme (refines
polylines), loaded from a built-in name, a .json file, a dict or JSON text.

Parameters are keyword arguments, as ``--param name=value`` on the command line::

    loop = Scheme.load("loop", beta="warren")
    fp = Scheme.load("four-point", w=0.05)
    mine = Scheme.from_dict({"name": "my-scheme", "split": "quad", ...})
)doc")
      .def_static(
          "load",
          [](const std::string& name_or_path, py::kwargs kwargs) {
            return load_scheme_handle(name_or_path, false, name_or_path, overrides_from(kwargs));
          },
          py::arg("name_or_path"),
          R"doc(Load a built-in scheme by name (see ``schemes()``) or a scheme file (.json) by path.

Keyword arguments set the scheme's parameters. Raises subdivkit.Error with the command line's
message for unknown names, bad files and bad parameter values.)doc")
      .def_static(
          "from_json",
          [](const std::string& text, const std::string& label, py::kwargs kwargs) {
            return load_scheme_handle(text, true, label, overrides_from(kwargs));
          },
          py::arg("text"), py::kw_only(), py::arg("label") = "<json>",
          R"doc(A scheme from JSON text in the scheme language (docs/scheme-format.md).

``label`` stands for the file name in error messages. Keyword arguments set parameters.)doc")
      .def_static(
          "from_dict",
          [](const py::dict& d, const std::string& label, py::kwargs kwargs) {
            return load_scheme_handle(text_from_dict(d), true, label, overrides_from(kwargs));
          },
          py::arg("scheme"), py::kw_only(), py::arg("label") = "<dict>",
          R"doc(A scheme from a dict with the structure of a scheme .json file (docs/scheme-format.md).

Useful in notebooks: write the rules inline, refine, analyse, change a weight, repeat.
``label`` stands for the file name in error messages. Keyword arguments set parameters.)doc")
      .def(
          "with_params",
          [](const SchemeHandle& h, py::kwargs kwargs) {
            subdiv::ParameterOverrides o = h.overrides;
            for (auto& [k, v] : overrides_from(kwargs)) o[k] = v;
            return load_scheme_handle(h.source, h.from_text, h.label, o);
          },
          "The same scheme loaded again with these parameter values (the others keep theirs).")
      .def_property_readonly("name", &SchemeHandle::name, "The scheme's name.")
      .def_property_readonly("kind", [](const SchemeHandle& h) { return h.kind; },
                             "'surface' (refines polygon meshes) or 'curve' (refines polylines).")
      .def_property_readonly(
          "description",
          [](const SchemeHandle& h) { return h.kind == "curve" ? h.curve->description : h.surface->description; },
          "The scheme's description.")
      .def_property_readonly(
          "path", [](const SchemeHandle& h) { return h.kind == "curve" ? h.curve->path : h.surface->path; },
          "The file it was loaded from (the label for dicts and JSON text).")
      .def_property_readonly(
          "parameters",
          [](const SchemeHandle& h) {
            py::dict d;
            for (const auto& p : specs_of(h))
              d[py::str(p.name)] = p.is_choice ? py::object(py::str(p.choice)) : py::object(py::float_(p.value));
            return d;
          },
          "The parameters' current values, name -> number (or the chosen string for choice parameters).")
      .def_property_readonly(
          "parameter_info",
          [](const SchemeHandle& h) {
            py::list l;
            for (const auto& p : specs_of(h)) l.append(parameter_info(p));
            return l;
          },
          "Each parameter's description, value and valid range (or choices), as dicts.")
      .def_property_readonly(
          "arity", [](const SchemeHandle& h) { return h.kind == "curve" ? h.curve->arity : 0; },
          "Curve schemes: new points per old point (2 binary, 3 ternary); 0 for surface schemes.")
      .def("__repr__", [](const SchemeHandle& h) {
        std::string params;
        for (const auto& [k, v] : h.overrides) params += fmt::format(", {}={}", k, v);
        return fmt::format("subdivkit.Scheme({}, kind={}{})", subdiv::quoted(h.name()), subdiv::quoted(h.kind), params);
      });
  refuse_bare_new(scheme, "Scheme.load(name_or_path), Scheme.from_json(text) or Scheme.from_dict(d) makes one");

  m.def(
      "schemes",
      [] {
        py::list out;
        for (const auto& s : subdiv::list_schemes()) {
          py::dict d;
          d["name"] = s.name, d["kind"] = s.kind, d["description"] = s.description;
          d["path"] = s.path, d["origin"] = s.origin;
          out.append(d);
        }
        return out;
      },
      R"doc(Every scheme that Scheme.load finds by name, sorted by name, as dicts with keys
name, kind ('surface' or 'curve'), description, path and origin ('built-in',
'SUBDIV_SCHEME_PATH' or 'plugin NAME') -- what ``subdiv schemes`` lists.)doc");
}

}  // namespace subdivkit
