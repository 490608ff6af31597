// subdivkit.Evaluator's engine side: a surface's topology refined once (refine_topology)
// and an engine Evaluator over it (engine/evaluator.h), which then carries any number of
// value sets (animation frames, edits) from the base level to the finest. The GIL is
// released while the library works, as in refine.
#include <climits>
#include <cmath>
#include <fmt/format.h>
#include <mutex>
#include <span>

#include "bindings.h"
#include "framework/util/quoted_text.h"

namespace subdivkit {
namespace {

// The topology, the schemes it was refined with and the engine's Evaluator, which refers to
// both, kept together in one object that never moves (pybind11 holds it by pointer).
// Members are destroyed in the reverse order of their declaration: the Evaluator first,
// then the hierarchy and the schemes it refers to.
class PreparedRefinement {
public:
  // Builds the hierarchy and prepares every step: call it without the GIL.
  PreparedRefinement(SchemeChoice choice, const subdiv::MeshData& base, const std::string& name,
                     const subdiv::RefineOptions& options, int threads)
      : threads_(threads),
        choice_(std::move(choice)),
        topology_(subdiv::refine_topology(choice_.sequence.runs, surface_base(base, name, choice_), options)),
        finest_(subdiv::mesh_from_level(topology_.levels.back(), {})),
        evaluator_(choice_.sequence.runs, topology_, options) {}
  PreparedRefinement(const PreparedRefinement&) = delete;
  PreparedRefinement& operator=(const PreparedRefinement&) = delete;

  int levels() const { return evaluator_.levels(); }
  Index base_count() const { return evaluator_.base_vertex_count(); }
  Index finest_count() const { return evaluator_.finest_vertex_count(); }

  // The finest level's faces and feature tags as mesh_to_python's arrays, with no points
  // (the Python side sets them): the same faces, creases and corners refine() returns.
  py::dict topology() const {
    subdiv::MeshData copy = finest_;
    return mesh_to_python(std::move(copy));
  }

  // Values of the base level's points (base count x channels, vertex-major) at the
  // finest level's points. The evaluator's buffers are shared by every call, so calls from
  // several Python threads take turns (the GIL is released first: waiting for a turn must
  // not hold it).
  std::vector<double> evaluate(std::span<const double> base, int channels) {
    const subdiv::ThreadLimit limit(threads_);
    const std::lock_guard<std::mutex> turn(busy_);
    return evaluator_.evaluate(base, channels);
  }

private:
  const int threads_;          // every call's `threads` limit, as refine's
  const SchemeChoice choice_;  // the loaded schemes (shared_ptrs), which the runs point into
  const subdiv::Hierarchy topology_;
  const subdiv::MeshData finest_;
  subdiv::Evaluator evaluator_;
  std::mutex busy_;
};

// What `refine` refuses in positions (mesh_validate's check_positions), refused in any
// per-point data before it reaches the rules, which would spread it to the neighbours.
void check_finite(std::span<const double> values, int channels) {
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw subdiv::Error(fmt::format("Evaluator.evaluate: point {} has a non-finite value ({}) in column {}; "
                                      "refinement would spread it to the neighbours: fix or remove it",
                                      i / size_t(channels), values[i], i % size_t(channels)));
}

std::unique_ptr<PreparedRefinement> make_evaluator(py::handle mesh, py::handle scheme, py::handle params, int levels,
                                                   const std::string& boundary, const std::string& crease_method,
                                                   int threads, int start_level) {
  check_levels(levels);
  const subdiv::RefineOptions options = refine_options(boundary, crease_method, threads, start_level);
  const subdiv::MeshData base = mesh_from_python(mesh);
  const std::string name = mesh_name(mesh);
  SchemeChoice choice = scheme_choice_from(scheme, levels, params);
  if (choice.is_curve())
    throw subdiv::Error(fmt::format("Evaluator: {} is a curve scheme; the Evaluator refines surfaces. For "
                                    "polylines, stencils(mesh, {}, {}, composed=True) gives the matrix to reuse",
                                    subdiv::quoted(choice.label), subdiv::quoted(choice.label), levels));
  py::gil_scoped_release unlocked;
  const subdiv::ThreadLimit limit(threads);
  return std::make_unique<PreparedRefinement>(std::move(choice), base, name, options, threads);
}

py::array_t<double> evaluate(PreparedRefinement& e, py::handle points) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  if (!a) {
    PyErr_Clear();
    throw subdiv::Error("Evaluator.evaluate: points cannot be read as float64 values");
  }
  const Index rows = e.base_count();
  if (a.ndim() != 2 || a.shape(0) != rows || a.shape(1) < 1 || a.shape(1) > INT_MAX)
    throw subdiv::Error(fmt::format("Evaluator.evaluate: expected shape ({}, c) with c >= 1 (one row per base "
                                    "point), got {}", rows, std::string(py::str(py::tuple(a.attr("shape"))))));
  const int channels = int(a.shape(1));
  const std::span<const double> base(a.data(), size_t(a.size()));
  std::vector<double> finest;
  {
    py::gil_scoped_release unlocked;
    check_finite(base, channels);
    finest = e.evaluate(base, channels);
  }
  return adopt(std::move(finest), {py::ssize_t(e.finest_count()), py::ssize_t(channels)});
}

}  // namespace

void bind_evaluator(py::module_& m) {
  auto evaluator = py::class_<PreparedRefinement>(
      m, "_Evaluator", "A surface's topology refined once, for repeated evaluation (subdivkit.Evaluator wraps it).");
  evaluator
      .def("evaluate", &evaluate, py::arg("points"),
           "(base points, c) float64 -> (finest points, c) float64, without the GIL.")
      .def("topology", &PreparedRefinement::topology,
           "The finest level's faces, creases and corners as Mesh._from_arrays takes them (points empty).")
      .def_property_readonly("levels", [](const PreparedRefinement& e) { return e.levels(); })
      .def_property_readonly("n_base_points", [](const PreparedRefinement& e) { return e.base_count(); })
      .def_property_readonly("n_points", [](const PreparedRefinement& e) { return e.finest_count(); });
  refuse_bare_new(evaluator, "subdivkit.Evaluator(mesh, scheme, ...) prepares one");
  m.def("_prepare_evaluator", &make_evaluator, py::arg("mesh"), py::arg("scheme"), py::arg("params"),
        py::arg("levels"), py::arg("boundary"), py::arg("crease_method"), py::arg("threads"), py::arg("start_level"),
        "The _Evaluator of subdivkit.Evaluator.");
}

}  // namespace subdivkit
