// subdivkit.refine_adaptive: feature-adaptive refinement through the pipeline's adaptive
// request (framework/pipeline/adaptive_request.h), the same as `subdiv refine --adaptive L`.
#include "bindings.h"
#include "framework/pipeline/adaptive_request.h"

namespace subdivkit {
namespace {

py::dict refine_adaptive(py::handle mesh, py::handle scheme, py::handle params, int levels, double tolerance,
                         bool limit, const std::string& boundary, const std::string& crease_method,
                         double feature_angle, int threads, py::handle point_data, py::handle face_varying,
                         const std::string& fvar_boundary, py::handle progress, const std::string& transitions) {
  subdiv::AdaptiveRequest r;
  r.refine.mesh = mesh_from_python(mesh);
  // Point arrays are carried to the adaptive mesh like the positions.
  r.refine.mesh.point_data = data_arrays_from(point_data, r.refine.mesh.vertex_count(), "point data");
  // Face-varying arrays are evaluated on the limit at the corners (with limit=True).
  r.refine.mesh.face_varying = face_varying_from(face_varying, Index(r.refine.mesh.face_vertices.size()));
  r.refine.shape.face_varying = subdiv::face_varying_from_name(fvar_boundary, "fvar_boundary=");
  r.refine.mesh_name = mesh_name(mesh);
  r.refine.scheme = scheme_source_from(scheme, params);
  r.refine.shape.boundary = boundary_from(boundary);
  r.refine.shape.crease_method = crease_method_from(crease_method);
  r.refine.feature_angle = feature_angle;
  r.refine.levels = levels;
  r.tolerance = tolerance;
  r.limit = limit;
  r.transitions = subdiv::transitions_from_name(transitions);
  if (!progress.is_none()) report_progress(r.refine, progress);
  subdiv::AdaptiveResult result;
  {
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit limit_threads(threads);
    result = subdiv::refine_adaptive_request(std::move(r));
  }
  subdiv::AdaptiveMesh& a = result.mesh;
  py::dict out;
  out["summary"] = subdiv::adaptive_summary(result);
  out["warnings"] = result.warnings;
  out["notes"] = result.notes;  // what was left out, and why
  out["uniform_faces"] = a.uniform_faces;
  out["split_faces"] = a.split_faces;
  const auto faces = py::ssize_t(a.face_level.size()), corners = py::ssize_t(a.corner_uv.size());
  std::vector<double> uv;
  for (const auto& c : a.corner_uv) uv.insert(uv.end(), {c[0], c[1]});
  out["corner_uv"] = adopt(std::move(uv), {corners, 2});
  out["face_level"] = adopt(std::vector<Index>(a.face_level.begin(), a.face_level.end()), {faces});
  out["base_face"] = adopt(std::move(a.base_face), {faces});
  // The mesh with the point arrays carried like the positions; the cell arrays are the
  // face_level and base_face returned above.
  subdiv::MeshData m = subdiv::adaptive_mesh_data(std::move(a), std::move(result.point_arrays), std::move(result.face_varying));
  m.cell_data.clear();
  out["face_varying"] = face_varying_to_python(std::move(m.face_varying));
  m.face_varying.clear();
  out["point_roles"] = roles_to_python(m.point_data);
  out["point_data"] = data_arrays_to_python(std::move(m.point_data));
  m.point_data.clear();
  out["mesh"] = mesh_to_python(std::move(m));
  return out;
}

}  // namespace

void bind_adaptive(py::module_& m) {
  m.def("_refine_adaptive", &refine_adaptive, py::arg("mesh"), py::arg("scheme"), py::arg("params"),
        py::arg("levels"), py::arg("tolerance"), py::arg("limit"), py::arg("boundary"), py::arg("crease_method"),
        py::arg("feature_angle"), py::arg("threads"), py::arg("point_data"), py::arg("face_varying"),
        py::arg("fvar_boundary"), py::arg("progress"), py::arg("transitions"), "The work of subdivkit.refine_adaptive.");
}

}  // namespace subdivkit
