// subdivkit.LimitSurface and subdivkit.evaluate: the exact limit surface at (face, u, v),
// through the pipeline's evaluation request (framework/pipeline/evaluate_request.h), the
// same as `subdiv evaluate`.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bindings.h"
#include "framework/pipeline/approximation_request.h"
#include "framework/pipeline/limit_mesh.h"
#include "framework/pipeline/rational_weights.h"
#include "framework/util/quoted_text.h"

namespace subdivkit {
namespace {

// The prepared surface, shared by the Python object and the calls running without the GIL.
struct LimitSurfaceHandle {
  std::shared_ptr<const subdiv::PreparedEvaluation> prepared;
};

LimitSurfaceHandle prepare(py::handle mesh, py::handle scheme, py::handle params, const std::string& boundary,
                           const std::string& crease_method, double feature_angle, py::handle face_varying,
                           const std::string& fvar_boundary) {
  subdiv::EvaluateRequest r;
  r.mesh = mesh_from_python(mesh);
  // Rational weights (docs/rational.md): the point array "weight", as refine() takes it.
  const py::dict point_data = mesh.attr("point_data");
  if (point_data.contains(subdiv::kWeightArrayName)) {
    std::vector<double> w = doubles_from(point_data[subdiv::kWeightArrayName], "point_data['weight']");
    if (w.size() != size_t(r.mesh.vertex_count()))
      throw subdiv::Error(fmt::format("point_data['weight']: {} values for {} points; give one weight per point",
                                      w.size(), r.mesh.vertex_count()));
    r.mesh.point_data.push_back({subdiv::kWeightArrayName, 1, std::move(w)});
  }
  r.mesh.face_varying = face_varying_from(face_varying, Index(r.mesh.face_vertices.size()));
  r.shape.face_varying = subdiv::face_varying_from_name(fvar_boundary, "fvar_boundary=");
  r.mesh_name = mesh_name(mesh);
  r.scheme = scheme_source_from(scheme, params);
  r.shape.boundary = boundary_from(boundary);
  r.shape.crease_method = crease_method_from(crease_method);
  r.feature_angle = feature_angle;
  LimitSurfaceHandle h;
  py::gil_scoped_release unlocked;
  h.prepared = std::make_shared<const subdiv::PreparedEvaluation>(subdiv::prepare_evaluation(std::move(r)));
  return h;
}

// (n,) faces and (n, 2) parameters, as the Python layer has shaped them.
void points_from(py::handle faces, py::handle uv, std::vector<Index>& f, std::vector<double>& p) {
  f = indices_from(faces, "faces");
  p = doubles_from(uv, "uv");
}

py::dict to_python(subdiv::EvaluatedPoints&& r, int derivatives) {
  const py::ssize_t n = r.count, c = r.channels;
  py::dict out;
  out["points"] = adopt(std::move(r.position), {n, c});
  const char* names[] = {"du", "dv", "duu", "duv", "dvv"};
  std::vector<double>* arrays[] = {&r.du, &r.dv, &r.duu, &r.duv, &r.dvv};
  for (int k = 0; k < 5; ++k)
    if (k < 2 ? derivatives >= 1 : derivatives >= 2) out[names[k]] = adopt(std::move(*arrays[k]), {n, c});
  return out;
}

py::dict evaluate(const LimitSurfaceHandle& h, py::handle faces, py::handle uv, int derivatives, py::handle values,
                  int channels, int threads) {
  std::vector<Index> f;
  std::vector<double> p, v;
  points_from(faces, uv, f, p);
  if (!values.is_none()) v = doubles_from(values, "points");
  subdiv::EvaluatedPoints r;
  {
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit limit(threads);
    r = subdiv::evaluate_limit_points(*h.prepared, f, p, derivatives, v, values.is_none() ? 3 : channels);
  }
  return to_python(std::move(r), derivatives);
}

py::dict evaluate_face_varying(const LimitSurfaceHandle& h, const std::string& name, py::handle faces, py::handle uv,
                               int derivatives, int threads) {
  std::vector<Index> f;
  std::vector<double> p;
  points_from(faces, uv, f, p);
  const auto& channels = h.prepared->face_varying;
  size_t k = 0;
  while (k < channels.size() && channels[k].name != name) ++k;
  if (k == channels.size()) {
    std::vector<std::string> names;
    for (const auto& c : channels) names.push_back(subdiv::quoted(c.name));
    throw subdiv::Error(fmt::format("face-varying array {}: the mesh has {}", subdiv::quoted(name),
                                    names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "))));
  }
  subdiv::EvaluatedPoints r;
  {
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit limit(threads);
    r = subdiv::evaluate_face_varying(*h.prepared, k, f, p, derivatives);
  }
  return to_python(std::move(r), derivatives);
}

py::dict matrix_to_python(subdiv::LimitStencilMatrices::Matrix&& m, Index rows, Index columns) {
  py::dict d;
  const auto entries = py::ssize_t(m.weights.size());
  d["shape"] = py::make_tuple(py::ssize_t(rows), py::ssize_t(columns));
  d["indptr"] = adopt(std::move(m.offsets), {py::ssize_t(rows) + 1});
  d["indices"] = adopt(std::move(m.columns), {entries});
  d["data"] = adopt(std::move(m.weights), {entries});
  return d;
}

py::dict stencils(const LimitSurfaceHandle& h, py::handle faces, py::handle uv, int derivatives, int threads) {
  std::vector<Index> f;
  std::vector<double> p;
  points_from(faces, uv, f, p);
  subdiv::LimitStencilMatrices s;
  {
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit limit(threads);
    s = subdiv::limit_stencil_matrices(*h.prepared, f, p, derivatives);
  }
  py::dict out;
  out["points"] = matrix_to_python(std::move(s.position), s.rows, s.columns);
  const char* names[] = {"du", "dv", "duu", "duv", "dvv"};
  subdiv::LimitStencilMatrices::Matrix* matrices[] = {&s.du, &s.dv, &s.duu, &s.duv, &s.dvv};
  for (int k = 0; k < 5; ++k)
    if (k < 2 ? derivatives >= 1 : derivatives >= 2)
      out[names[k]] = matrix_to_python(std::move(*matrices[k]), s.rows, s.columns);
  const auto n = py::ssize_t(s.rows);
  out["has_first"] = adopt(std::move(s.has_first), {n});
  out["has_second"] = adopt(std::move(s.has_second), {n});
  return out;
}

}  // namespace

// The sampled limit surface as `subdiv evaluate --samples N` writes it (pipeline/limit_mesh.h),
// as arrays for subdivkit.Mesh.
py::dict tessellate(const LimitSurfaceHandle& h, int samples, int threads, py::handle progress) {
  subdiv::MeshData m;
  {
    std::function<void(const std::string&)> say;
    std::function<void(double)> fraction;
    if (!progress.is_none()) progress_callbacks(progress, say, fraction);
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit limit(threads);
    m = subdiv::sampled_limit_mesh(*h.prepared, samples, say, fraction);
  }
  std::vector<subdiv::DataArray> point_data = std::move(m.point_data), cell_data = std::move(m.cell_data);
  std::vector<subdiv::FaceVaryingArray> face_varying = std::move(m.face_varying);
  m.point_data.clear(), m.cell_data.clear(), m.face_varying.clear();
  std::vector<std::string> warnings = std::move(m.warnings);
  py::dict d = mesh_to_python(std::move(m));
  d["warnings"] = warnings;
  d["point_roles"] = roles_to_python(point_data);
  d["cell_roles"] = roles_to_python(cell_data);
  d["point_data"] = data_arrays_to_python(std::move(point_data));
  d["cell_data"] = data_arrays_to_python(std::move(cell_data));
  d["face_varying"] = face_varying_to_python(std::move(face_varying));
  return d;
}

// Patches tessellated as `subdiv evaluate --approximate bezier|gregory --samples N` writes
// them (pipeline/approximation_request.h), with their distances to the exact limit;
// `patches` builds them from the prepared surface.
template <typename BuildPatches>
py::dict approximated_mesh(const LimitSurfaceHandle& h, int samples, int threads, const BuildPatches& patches) {
  subdiv::MeshData m;
  subdiv::ApproximationDistances d;
  {
    py::gil_scoped_release unlocked;
    const subdiv::ThreadLimit limit(threads);
    m = subdiv::approximated_limit_mesh(*h.prepared, patches(*h.prepared), samples, d);
  }
  std::vector<subdiv::DataArray> point_data = std::move(m.point_data), cell_data = std::move(m.cell_data);
  m.point_data.clear(), m.cell_data.clear();
  std::vector<std::string> warnings = std::move(m.warnings);
  py::dict out = mesh_to_python(std::move(m));
  out["warnings"] = warnings;
  out["point_roles"] = roles_to_python(point_data);
  out["cell_roles"] = roles_to_python(cell_data);
  out["point_data"] = data_arrays_to_python(std::move(point_data));
  out["cell_data"] = data_arrays_to_python(std::move(cell_data));
  out["face_varying"] = py::list();
  out["largest"] = d.largest;
  out["mean"] = d.mean;
  out["largest_face"] = d.largest_face;
  return out;
}

// Loop & Schaefer's (2008) bicubic patches.
py::dict approximate_bezier(const LimitSurfaceHandle& h, int samples, int threads) {
  return approximated_mesh(h, samples, threads, subdiv::approximation_patches);
}

// Loop, Schaefer, Ni & Castaño's (2009) Gregory patches.
py::dict approximate_gregory(const LimitSurfaceHandle& h, int samples, int threads) {
  return approximated_mesh(h, samples, threads, subdiv::gregory_approximation_patches);
}

void bind_limit_surface(py::module_& m) {
  auto surface = py::class_<LimitSurfaceHandle>(m, "_LimitSurface");
  m.def("_prepare_limit_surface", &prepare, py::arg("mesh"), py::arg("scheme"), py::arg("params"),
        py::arg("boundary"), py::arg("crease_method"), py::arg("feature_angle"), py::arg("face_varying"),
        py::arg("fvar_boundary"), "The _LimitSurface of subdivkit.LimitSurface.");
  surface
      .def("evaluate_face_varying", &evaluate_face_varying, py::arg("name"), py::arg("faces"), py::arg("uv"),
           py::arg("derivatives"), py::arg("threads"))
      .def_property_readonly("face_varying",
                             [](const LimitSurfaceHandle& h) {
                               std::vector<std::string> names;
                               for (const auto& c : h.prepared->face_varying) names.push_back(c.name);
                               return names;
                             })
      .def("evaluate", &evaluate, py::arg("faces"), py::arg("uv"), py::arg("derivatives"), py::arg("values"),
           py::arg("channels"), py::arg("threads"))
      .def("stencils", &stencils, py::arg("faces"), py::arg("uv"), py::arg("derivatives"), py::arg("threads"))
      .def("tessellate", &tessellate, py::arg("samples"), py::arg("threads"), py::arg("progress") = py::none())
      .def("approximate_bezier", &approximate_bezier, py::arg("samples"), py::arg("threads"))
      .def("approximate_gregory", &approximate_gregory, py::arg("samples"), py::arg("threads"))
      .def_property_readonly("scheme_label", [](const LimitSurfaceHandle& h) { return h.prepared->scheme_label; })
      .def_property_readonly("triangles", [](const LimitSurfaceHandle& h) { return h.prepared->surface->triangles(); })
      .def_property_readonly("vertex_count",
                             [](const LimitSurfaceHandle& h) { return h.prepared->request_vertex_count; })
      .def_property_readonly("face_count",
                             [](const LimitSurfaceHandle& h) { return h.prepared->surface->base().face_count(); })
      .def_property_readonly("warnings", [](const LimitSurfaceHandle& h) { return h.prepared->warnings; });
  refuse_bare_new(surface, "subdivkit.LimitSurface(mesh, scheme, ...) prepares one");
}

}  // namespace subdivkit
