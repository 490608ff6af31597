// parameterize: Tutte's embedding of a disc-like mesh (framework/parameterize), the UVs as
// NumPy arrays; subdivkit/parameterize.py makes the Mesh with them.
#include "bindings.h"

namespace subdivkit {
namespace {

py::dict parameterize(py::handle mesh, const std::string& boundary, py::handle corners, const std::string& weights) {
  subdiv::TutteOptions o;
  o.boundary = subdiv::boundary_shape_from_name(boundary, "boundary=");
  o.weights = subdiv::tutte_weights_from_name(weights, "weights=");
  if (!corners.is_none()) o.corners = indices_from(corners, "corners");
  if (!o.corners.empty() && o.boundary != subdiv::BoundaryShape::Square)
    throw subdiv::Error("corners= places the corners of a square boundary; add boundary=\"square\"");
  subdiv::MeshData data = mesh_from_python(mesh);
  const std::string name = mesh_name(mesh);
  subdiv::TutteResult r;
  {
    py::gil_scoped_release release;
    r = subdiv::tutte_embedding(subdiv::level_from_mesh(data, name), data.positions, o, name);
  }
  const auto n = py::ssize_t(r.uv.size() / 2), b = py::ssize_t(r.boundary.size()), c = py::ssize_t(r.corners.size());
  py::dict out;
  out["uv"] = adopt(std::move(r.uv), {n, 2});
  out["boundary"] = adopt(std::move(r.boundary), {b});
  out["corners"] = adopt(std::move(r.corners), {c});
  return out;
}

}  // namespace

void bind_parameterize(py::module_& m) {
  m.def("_parameterize", &parameterize, py::arg("mesh"), py::arg("boundary"), py::arg("corners"), py::arg("weights"));
}

}  // namespace subdivkit
