// limit_positions and interpolate: points on the limit surface (or curve) and progressive
// interpolation, which moves control points until the limit passes through the targets.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "bindings.h"

namespace subdivkit {
namespace {

// The limit operator of a mesh under a scheme, as `subdiv interpolate` chooses it: curve
// limit stencils for polylines, the checked limit masks (limit_selection.h) for surfaces.
struct LimitOperator {
  subdiv::StencilTable table;
  std::string description;
};

LimitOperator limit_operator(const subdiv::MeshData& mesh, const std::string& name, const SchemeChoice& c,
                             const std::string& boundary, int start_level) {
  if (c.is_curve()) {
    const subdiv::CurveLevel level = subdiv::curve_level_from_mesh(mesh, name);
    return {subdiv::curve_limit_stencils(*c.single->curve, level), "limit points of " + c.label};
  }
  if (mesh.face_count() == 0)
    throw subdiv::Error(fmt::format("{}: the mesh has no faces; surface schemes need a surface mesh{}", name,
                                    mesh.line_count() ? " (polylines take a curve scheme, e.g. 'cubic-bspline')" : ""));
  const subdiv::Level base = subdiv::level_from_mesh(mesh, name);
  const subdiv::LimitChoice choice =
      subdiv::select_limit(c.sequence, base, limit_selection_options(boundary, start_level));
  return {choice.evaluator->limit_stencils(base, start_level), choice.description};
}

py::dict limit_positions(py::handle mesh, py::handle scheme, py::handle params, const std::string& boundary,
                         const std::string& crease_method, int start_level) {
  subdiv::MeshData m = mesh_from_python(mesh);
  const std::string name = mesh_name(mesh);
  const SchemeChoice c = scheme_choice_from(scheme, 1, params);
  py::dict out;
  if (c.is_curve()) {
    std::vector<double> points;
    {
      py::gil_scoped_release unlocked;
      points = limit_operator(m, name, c, boundary, start_level).table.apply(m.positions, 3);
    }
    const auto n = py::ssize_t(points.size() / 3);
    out["points"] = adopt(std::move(points), {n, 3});
    return out;
  }
  if (c.sequence.schemes.size() != 1)
    throw subdiv::Error(fmt::format("limit_positions: '{}' is a sequence; give one scheme (its limit is the limit "
                                    "of the scheme that repeats)", c.label));
  if (m.face_count() == 0) throw subdiv::Error(fmt::format("{}: the mesh has no faces", name));
  subdiv::LimitResult r;
  {
    py::gil_scoped_release unlocked;
    const subdiv::Level level = subdiv::level_from_mesh(m, name);
    r = subdiv::limit_positions(*c.sequence.schemes.front(), level, m.positions,
                                limit_options(boundary, crease_method, start_level));
  }
  const auto n = py::ssize_t(r.positions.size() / 3);
  out["points"] = adopt(std::move(r.positions), {n, 3});
  out["normals"] = adopt(std::move(r.normals), {n, 3});
  out["exact"] = adopt(std::move(r.exact), {n});
  out["normal_exact"] = adopt(std::move(r.normal_exact), {n});
  out["approximate_reasons"] = r.approximate_reasons;
  return out;
}

py::dict interpolate(py::handle mesh, py::handle scheme, py::handle params, py::handle moving_mask, double tolerance,
                     int max_iterations, const std::string& boundary, int threads) {
  subdiv::MeshData m = mesh_from_python(mesh);
  const std::string name = mesh_name(mesh);
  const SchemeChoice c = scheme_choice_from(scheme, 1, params);
  std::vector<std::uint8_t> moving;
  if (!moving_mask.is_none()) {
    for (Index v : indices_from(moving_mask, "select")) moving.push_back(v != 0);
    if (moving.size() != size_t(m.vertex_count()))
      throw subdiv::Error(fmt::format("select: {} flags for {} vertices", moving.size(), m.vertex_count()));
  }
  if (max_iterations < 0) throw subdiv::Error("max_iterations must be 0 or more");
  subdiv::ProgressiveOptions po;
  po.tolerance = tolerance >= 0 ? tolerance : subdiv::default_interpolation_tolerance(m.positions);
  po.max_iterations = max_iterations;
  LimitOperator limit;
  subdiv::ProgressiveResult r;
  {
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit thread_limit(threads);
    limit = limit_operator(m, name, c, boundary, 0);
    r = subdiv::progressive_interpolation(limit.table, m.positions, moving, po);
  }
  const auto n = py::ssize_t(m.vertex_count());
  std::vector<double> max_residual, rms_residual;
  for (const auto& h : r.history) max_residual.push_back(h.max_residual), rms_residual.push_back(h.rms_residual);
  const auto k = py::ssize_t(max_residual.size());
  py::dict out;
  out["points"] = adopt(std::move(r.control), {n, 3});
  out["limit"] = adopt(std::move(r.limit), {n, 3});
  out["iterations"] = r.iterations;
  out["converged"] = r.converged;
  out["tolerance"] = po.tolerance;
  out["max_residual"] = adopt(std::move(max_residual), {k});
  out["rms_residual"] = adopt(std::move(rms_residual), {k});
  out["limit_description"] = limit.description;
  return out;
}

}  // namespace

void bind_limits(py::module_& m) {
  m.def("_limit_positions", &limit_positions, py::arg("mesh"), py::arg("scheme"), py::arg("params"), py::arg("boundary"),
        py::arg("crease_method"), py::arg("start_level"), "Limit points (and normals) as arrays.");
  m.def("_interpolate", &interpolate, py::arg("mesh"), py::arg("scheme"), py::arg("params"), py::arg("moving"), py::arg("tolerance"),
        py::arg("max_iterations"), py::arg("boundary"), py::arg("threads"),
        "Progressive interpolation as arrays (subdivkit.interpolate wraps them).");
}

}  // namespace subdivkit
