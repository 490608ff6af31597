// Loading schemes for Python: by name or path as `--scheme` does, or from JSON text (a dict
// turned into JSON), with keyword arguments as `--param` overrides.
#include <fmt/format.h>

#include "bindings.h"

namespace subdivkit {

namespace {

// A scheme given as text: a name, a sequence "A:1,B", or a path (str or os.PathLike).
bool is_scheme_text(py::handle scheme) {
  return py::isinstance<py::str>(scheme) || py::isinstance(scheme, py::module_::import("os").attr("PathLike"));
}

}  // namespace

const std::string& SchemeHandle::name() const { return kind == "curve" ? curve->name : surface->name; }

SchemeHandle load_scheme_handle(const std::string& source, bool from_text, const std::string& label,
                                const subdiv::ParameterOverrides& overrides) {
  SchemeHandle h;
  h.source = source, h.from_text = from_text, h.label = label, h.overrides = overrides;
  try {
    if (from_text) {
      h.kind = subdiv::scheme_text_kind(source, label);
      if (h.kind == "curve") h.curve = subdiv::load_curve_text(source, label, overrides);
      else h.surface = subdiv::load_scheme_text(source, label, overrides);
    } else {
      h.kind = subdiv::scheme_kind(source);
      if (h.kind == "curve") h.curve = subdiv::load_curve(source, overrides);
      else h.surface = subdiv::load_scheme(source, overrides);
    }
  } catch (const subdiv::OptionError& e) {  // the parameters came as Scheme.load's keyword arguments
    throw subdiv::Error(e.spelled(python_keyword_spelling()));
  }
  return h;
}

subdiv::ParameterOverrides overrides_from(py::handle kwargs) {
  subdiv::ParameterOverrides out;
  if (kwargs.is_none()) return out;
  if (!py::isinstance<py::dict>(kwargs)) throw subdiv::Error("params: give a dict of parameter values");
  for (auto [key, value] : py::reinterpret_borrow<py::dict>(kwargs)) {
    const std::string name = py::str(key);
    if (py::isinstance<py::str>(value)) {
      out[name] = py::str(value);
    } else if (py::isinstance<py::bool_>(value)) {
      throw subdiv::Error(fmt::format("parameter {}={}: give a number or a string", name, std::string(py::repr(value))));
    } else if (py::isinstance<py::int_>(value)) {
      out[name] = py::str(value);
    } else {
      // Floats (and NumPy scalars) at full precision: repr() round-trips a double.
      try {
        out[name] = py::repr(py::float_(py::reinterpret_borrow<py::object>(value)));
      } catch (const py::error_already_set&) {
        throw subdiv::Error(fmt::format("parameter {}={}: give a number or a string", name,
                                        std::string(py::repr(value))));
      }
    }
  }
  return out;
}

SchemeChoice scheme_choice_from(py::handle scheme, int levels, py::handle params) {
  SchemeChoice c;
  const subdiv::ParameterOverrides overrides = overrides_from(params);
  if (py::isinstance<SchemeHandle>(scheme)) {
    const auto& h = scheme.cast<const SchemeHandle&>();
    subdiv::ParameterOverrides merged = h.overrides;
    for (const auto& [k, v] : overrides) merged[k] = v;
    c.single = std::make_shared<SchemeHandle>(overrides.empty() ? h
                                                                : load_scheme_handle(h.source, h.from_text, h.label, merged));
  } else if (is_scheme_text(scheme)) {
    const std::string spec = py::str(scheme);
    // A single curve scheme refines polylines; anything else is a surface sequence, which
    // also reports unknown names with the list of known ones.
    bool curve = false;
    try {
      curve = spec.find_first_of(",:") == std::string::npos && subdiv::scheme_kind(spec) == "curve";
    } catch (const subdiv::Error&) {
    }
    if (curve) c.single = std::make_shared<SchemeHandle>(load_scheme_handle(spec, false, spec, overrides));
    else c.sequence = subdiv::load_scheme_sequence(spec, levels, overrides);
    c.label = spec;
    return c;
  } else {
    throw subdiv::Error(fmt::format("scheme: expected a subdivkit.Scheme, a name or a path, got {}",
                                    std::string(py::str(py::type::of(scheme)))));
  }
  c.label = c.single->name();
  if (c.single->kind == "surface") {
    c.sequence.schemes = {c.single->surface};
    c.sequence.runs = {{c.single->surface.get(), levels}};
    c.sequence.total_levels = levels;
  }
  return c;
}

bool names_curve_scheme(py::handle scheme) {
  if (py::isinstance<SchemeHandle>(scheme)) return scheme.cast<const SchemeHandle&>().kind == "curve";
  if (!is_scheme_text(scheme)) return false;  // the surface path says what a scheme must be
  const std::string spec = py::str(scheme);
  try {
    return spec.find_first_of(",:") == std::string::npos && subdiv::scheme_kind(spec) == "curve";
  } catch (const subdiv::Error&) {
    return false;  // unknown names: the surface path lists the known ones
  }
}

subdiv::SchemeSource scheme_source_from(py::handle scheme, py::handle params) {
  subdiv::SchemeSource source;
  const subdiv::ParameterOverrides overrides = overrides_from(params);
  if (py::isinstance<SchemeHandle>(scheme)) {
    const auto& h = scheme.cast<const SchemeHandle&>();
    source.text = h.source, source.is_json_text = h.from_text, source.label = h.label;
    source.parameters = h.overrides;
  } else if (is_scheme_text(scheme)) {
    source.text = py::str(scheme);
  } else {  // str(None) would be looked up as a scheme named "None"
    throw subdiv::Error(fmt::format("scheme: expected a subdivkit.Scheme, a name or a path, got {}",
                                    std::string(py::str(py::type::of(scheme)))));
  }
  for (const auto& [k, v] : overrides) source.parameters[k] = v;
  return source;
}

}  // namespace subdivkit
