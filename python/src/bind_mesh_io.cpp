// Mesh files: the library's readers and writers (framework/io), chosen by extension.
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bindings.h"
#include "framework/io/mesh_seams.h"
#include "framework/io/mesh_validate.h"
#include "framework/util/quoted_text.h"

namespace subdivkit {
namespace {

// Whether a format other than .vtp/.pvd/.ply holds an array (the writers in framework/io:
// OFF takes normals, colours and UVs of points and colours of faces, OBJ per-point UVs as vt
// and rational weights as `v x y z w`).
bool format_holds(const std::string& ext, const subdiv::DataArray& a, bool per_point) {
  using subdiv::ArrayRole;
  if (ext == ".off")
    return per_point ? (a.role == ArrayRole::Normals && a.components == 3) ||
                           (a.role == ArrayRole::Color && a.components >= 3 && a.components <= 4) ||
                           (a.role == ArrayRole::TextureCoordinates && a.components == 2)
                     : a.role == ArrayRole::Color && a.components >= 3 && a.components <= 4;
  if (ext == ".obj")
    return per_point && ((a.role == ArrayRole::TextureCoordinates && a.components <= 3) ||
                         (a.name == "weight" && a.components == 1));
  return false;
}

// The arrays of `arrays` a format other than .vtp/.pvd/.ply leaves out, named for the warning.
std::vector<std::string> left_out(const std::string& ext, const std::vector<subdiv::DataArray>& arrays,
                                  bool per_point) {
  std::vector<std::string> names;
  for (const auto& a : arrays)
    if (!format_holds(ext, a, per_point)) names.push_back(fmt::format("{}", subdiv::quoted(a.name)));
  return names;
}

void write(const std::string& path, py::handle mesh, py::handle point_data, py::handle cell_data,
           py::handle face_varying) {
  subdiv::MeshData data = mesh_from_python(mesh);
  data.face_varying = face_varying_from(face_varying, Index(data.face_vertices.size()));
  data.point_data = data_arrays_from(point_data, data.vertex_count(), "point data");
  data.cell_data = data_arrays_from(cell_data, data.face_count(), "cell data");
  const std::string ext = subdiv::lowercase_extension(path);
  if (!subdiv::is_vtk_output(path)) {
    // PLY holds every array; OFF and OBJ those their roles fit (format_holds); the others
    // none. A warning, not an error: writing the geometry to .obj is a common, deliberate step.
    if (ext != ".ply") {
      std::vector<std::string> lost = left_out(ext, data.point_data, true);
      for (auto& name : left_out(ext, data.cell_data, false)) lost.push_back(std::move(name));
      if (!lost.empty() &&
          PyErr_WarnEx(PyExc_UserWarning,
                       subdiv::terminal_safe(fmt::format("write_mesh({}): {} files have no place for point or cell "
                                   "data {}; use .ply, .vtp or .pvd to keep it", subdiv::quoted(path), ext, fmt::join(lost, ", ")))
                           .c_str(), 1) < 0)
        throw py::error_already_set();  // warnings filtered into errors
    }
    // OBJ holds face-varying data as vt; the other formats get a point per side of a seam.
    if (ext != ".obj") data = subdiv::split_at_seams(data);
    py::gil_scoped_release unlocked;
    subdiv::write_mesh(path, data);
    return;
  }
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
        py::dict point_roles = roles_to_python(data.point_data), cell_roles = roles_to_python(data.cell_data);
        py::dict point_data = data_arrays_to_python(std::move(data.point_data));
        py::dict cell_data = data_arrays_to_python(std::move(data.cell_data));
        py::dict face_varying = face_varying_to_python(std::move(data.face_varying));
        py::dict out = mesh_to_python(std::move(data));
        out["point_data"] = point_data;
        out["cell_data"] = cell_data;
        out["point_roles"] = point_roles;
        out["cell_roles"] = cell_roles;
        out["face_varying"] = face_varying;
        return out;
      },
      py::arg("path"), "The arrays of a mesh file (subdivkit.read_mesh wraps them in a Mesh).");
  m.def("_write_mesh", &write, py::arg("path"), py::arg("mesh"), py::arg("point_data"), py::arg("cell_data"),
        py::arg("face_varying"),
        "Writes a Mesh (subdivkit.write_mesh checks the arguments first).");
  m.def(
      "_check_mesh",
      [](py::handle mesh, py::handle point_data, py::handle cell_data, const std::string& what) {
        subdiv::MeshData data = mesh_from_python(mesh);
        data.point_data = data_arrays_from(point_data, data.vertex_count(), "point data");
        data.cell_data = data_arrays_from(cell_data, data.face_count(), "cell data");
        subdiv::validate_mesh_data(data, what);
      },
      py::arg("mesh"), py::arg("point_data"), py::arg("cell_data"), py::arg("what"),
      "Refuses (subdivkit.Error) a Mesh that write_mesh would refuse: the conversions' check.");
  m.def("_input_formats", &subdiv::supported_input_formats, "The extensions read_mesh reads.");
  m.def("_output_formats", &subdiv::supported_output_formats, "The extensions write_mesh writes.");
}

}  // namespace subdivkit
