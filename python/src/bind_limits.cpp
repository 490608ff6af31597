// limit_positions and interpolate: points on the limit surface (or curve) and progressive
// interpolation, which moves control points until the limit passes through the targets.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "bindings.h"
#include "framework/limit/corner_limit.h"
#include "framework/util/quoted_text.h"

namespace subdivkit {
namespace {

// The request `subdiv interpolate` makes (framework/pipeline/interpolate_request.h).
subdiv::InterpolateRequest interpolate_request(py::handle mesh, py::handle scheme, py::handle params,
                                               const std::string& boundary, int start_level) {
  subdiv::InterpolateRequest r;
  r.mesh = mesh_from_python(mesh);
  r.mesh_name = mesh_name(mesh);
  r.scheme = scheme_source_from(scheme, params);
  r.boundary = boundary_from(boundary);
  r.start_level = start_level;
  return r;
}

py::dict limit_positions(py::handle mesh, py::handle scheme, py::handle params, const std::string& boundary,
                         const std::string& crease_method, int start_level) {
  py::dict out;
  if (names_curve_scheme(scheme)) {
    const subdiv::InterpolateRequest request = interpolate_request(mesh, scheme, params, boundary, start_level);
    std::vector<double> points;
    {
      py::gil_scoped_release unlocked;
      points = subdiv::limit_operator(request).table.apply(request.mesh.positions, 3);
    }
    const auto n = py::ssize_t(points.size() / 3);
    out["points"] = adopt(std::move(points), {n, 3});
    return out;
  }
  subdiv::MeshData m = mesh_from_python(mesh);
  const std::string name = mesh_name(mesh);
  const SchemeChoice c = scheme_choice_from(scheme, 1, params);
  if (c.sequence.schemes.size() != 1)
    throw subdiv::Error(fmt::format("limit_positions: {} is a sequence; give one scheme (its limit is the limit "
                                    "of the scheme that repeats)", subdiv::quoted(c.label)));
  if (m.face_count() == 0) throw subdiv::Error(fmt::format("{}: the mesh has no faces", name));
  subdiv::LimitResult r;
  std::string not_c1;
  {
    py::gil_scoped_release unlocked;
    const subdiv::Level level = subdiv::level_from_mesh(m, name);
    const subdiv::Scheme& s = *c.sequence.schemes.front();
    const subdiv::LimitOptions options = limit_options(boundary, crease_method, start_level);
    r = subdiv::limit_positions(s, level, m.positions, options);
    // A scheme that is not C1 where the mesh is regular has no normals (refine --limit leaves
    // them out): zero, "where none exists", with the reason.
    if (const std::string off = subdiv::SchemeLimits(s, options).regular_not_c1(); !off.empty()) {
      not_c1 = subdiv::not_c1(s, "at a regular vertex " + off);
      std::fill(r.normals.begin(), r.normals.end(), 0.0);
      std::fill(r.normal_exact.begin(), r.normal_exact.end(), std::uint8_t(0));
      r.approximate_reasons.push_back(not_c1);
    }
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
  subdiv::InterpolateRequest request = interpolate_request(mesh, scheme, params, boundary, 0);
  if (!moving_mask.is_none())
    for (Index v : indices_from(moving_mask, "select")) request.moving.push_back(v != 0);
  request.tolerance = tolerance;
  request.max_iterations = max_iterations;
  const auto n = py::ssize_t(request.mesh.vertex_count());
  subdiv::InterpolateResult r;
  {
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit thread_limit(threads);
    r = subdiv::interpolate_mesh(std::move(request));
  }
  std::vector<double> max_residual, rms_residual;
  for (const auto& h : r.iteration.history)
    max_residual.push_back(h.max_residual), rms_residual.push_back(h.rms_residual);
  const auto k = py::ssize_t(max_residual.size());
  py::dict out;
  out["points"] = adopt(std::move(r.iteration.control), {n, 3});
  out["limit"] = adopt(std::move(r.iteration.limit), {n, 3});
  out["iterations"] = r.iteration.iterations;
  out["converged"] = r.iteration.converged;
  out["tolerance"] = r.tolerance;
  out["max_residual"] = adopt(std::move(max_residual), {k});
  out["rms_residual"] = adopt(std::move(rms_residual), {k});
  out["limit_description"] = r.limit_description;
  out["fixed_note"] = r.fixed_note;
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
