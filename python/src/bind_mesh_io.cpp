// Mesh files: the library's readers and writers (framework/io), chosen by extension.
#include <filesystem>
#include <fmt/format.h>

#include "bindings.h"
#include "framework/io/mesh_seams.h"

namespace subdivkit {
namespace {

subdiv::DataArray data_array(NamedValues&& v) {
  return subdiv::DataArray{std::move(v.name), v.columns, std::move(v.values), false};
}

std::vector<NamedValues> named_values(std::vector<subdiv::DataArray>&& arrays) {
  std::vector<NamedValues> out;
  for (auto& a : arrays) out.push_back({std::move(a.name), std::move(a.values), a.components});
  return out;
}

void write(const std::string& path, py::handle mesh, py::handle point_data, py::handle cell_data,
           py::handle face_varying) {
  subdiv::MeshData data = mesh_from_python(mesh);
  data.face_varying = face_varying_from(face_varying, Index(data.face_vertices.size()));
  auto points = named_values_from(point_data, data.vertex_count(), "point data");
  auto cells = named_values_from(cell_data, data.face_count(), "cell data");
  const std::string ext = subdiv::lowercase_extension(path);
  if (!subdiv::is_vtk_output(path)) {
    // PLY holds every array; the others hold none (OFF only colours, normals and UVs, which
    // Python's plain arrays do not mark). A warning, not an error: writing the geometry to
    // .obj is a common, deliberate step.
    if (ext == ".ply") {
      for (auto& v : points) data.point_data.push_back(data_array(std::move(v)));
      for (auto& v : cells) data.cell_data.push_back(data_array(std::move(v)));
    } else if ((!points.empty() || !cells.empty()) &&
               PyErr_WarnEx(PyExc_UserWarning,
                            fmt::format("write_mesh('{}'): {} files hold no point or cell data; use .ply, .vtp or "
                                        ".pvd to keep it", path, ext).c_str(), 1) < 0) {
      throw py::error_already_set();  // warnings filtered into errors
    }
    // OBJ holds face-varying data as vt; the other formats get a point per side of a seam.
    if (ext != ".obj") data = subdiv::split_at_seams(data);
    py::gil_scoped_release unlocked;
    subdiv::write_mesh(path, data);
    return;
  }
  for (auto& v : points) data.point_data.push_back(data_array(std::move(v)));
  for (auto& v : cells) data.cell_data.push_back(data_array(std::move(v)));
  data = subdiv::split_at_seams(data);  // VTK holds per-point data: a point per side of a seam
  subdiv::OutputLevel level;
  level.mesh = &data;
  level.point_data = std::move(data.point_data);
  level.cell_data = std::move(data.cell_data);
  data.point_data.clear(), data.cell_data.clear();
  py::gil_scoped_release unlocked;
  if (ext == ".vtp") subdiv::write_vtp(path, level);
  else subdiv::write_pvd(path, std::span(&level, 1));
}

}  // namespace

void bind_mesh_io(py::module_& m) {
  m.def(
      "_read_mesh",
      [](const std::string& path) {
        subdiv::MeshData data;
        {
          py::gil_scoped_release unlocked;
          data = subdiv::read_mesh(path);
        }
        py::dict point_data = named_values_to_python(named_values(std::move(data.point_data)));
        py::dict cell_data = named_values_to_python(named_values(std::move(data.cell_data)));
        py::dict face_varying = face_varying_to_python(std::move(data.face_varying));
        py::dict out = mesh_to_python(std::move(data));
        out["point_data"] = point_data;
        out["cell_data"] = cell_data;
        out["face_varying"] = face_varying;
        return out;
      },
      py::arg("path"), "The arrays of a mesh file (subdivkit.read_mesh wraps them in a Mesh).");
  m.def("_write_mesh", &write, py::arg("path"), py::arg("mesh"), py::arg("point_data"), py::arg("cell_data"),
        py::arg("face_varying"),
        "Writes a Mesh (subdivkit.write_mesh checks the arguments first).");
  m.def("_input_formats", &subdiv::supported_input_formats, "The extensions read_mesh reads.");
  m.def("_output_formats", &subdiv::supported_output_formats, "The extensions write_mesh writes.");
}

}  // namespace subdivkit
