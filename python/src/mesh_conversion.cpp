// subdivkit.Mesh (python/subdivkit/mesh.py) to the library's MeshData and back. The Python
// class has already made its arrays C-contiguous with the right types; the arrays are read
// again here with conversion so that a hand-made object cannot crash the interpreter.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "bindings.h"
#include "framework/util/quoted_text.h"

namespace subdivkit {

std::string mesh_name(py::handle mesh) {
  if (py::hasattr(mesh, "name")) {
    py::object name = mesh.attr("name");
    if (!name.is_none()) return py::str(name);
  }
  return "mesh";
}

subdiv::MeshData mesh_from_python(py::handle mesh) {
  for (const char* attr : {"points", "face_indices", "face_offsets"})
    if (!py::hasattr(mesh, attr))
      throw subdiv::Error(fmt::format("expected a subdivkit.Mesh, got {} (it has no {})",
                                      std::string(py::str(py::type::of(mesh))), subdiv::quoted(attr)));
  const std::string name = mesh_name(mesh);
  subdiv::MeshData m;
  m.positions = doubles_from(mesh.attr("points"), name + ".points");
  const std::vector<Index> face_vertices = indices_from(mesh.attr("face_indices"), name + ".face_indices");
  const std::vector<Index> face_offsets = indices_from(mesh.attr("face_offsets"), name + ".face_offsets");
  m.face_vertices.assign(face_vertices.begin(), face_vertices.end());
  m.face_offsets.assign(face_offsets.begin(), face_offsets.end());
  if (m.face_offsets.empty()) m.face_offsets = {0};
  if (py::hasattr(mesh, "line_indices")) {
    m.line_vertices = indices_from(mesh.attr("line_indices"), name + ".line_indices");
    m.line_offsets = indices_from(mesh.attr("line_offsets"), name + ".line_offsets");
    if (m.line_offsets.empty()) m.line_offsets = {0};
  }
  if (py::hasattr(mesh, "creases")) {
    const auto pairs = indices_from(mesh.attr("creases"), name + ".creases");
    const auto sharpness = doubles_from(mesh.attr("crease_sharpness"), name + ".crease_sharpness");
    if (pairs.size() != 2 * sharpness.size())
      throw subdiv::Error(fmt::format("{}: {} crease edges but {} crease sharpness values; give one per edge",
                                      name, pairs.size() / 2, sharpness.size()));
    for (size_t i = 0; i < sharpness.size(); ++i) m.creases.push_back({pairs[2 * i], pairs[2 * i + 1], sharpness[i]});
  }
  if (py::hasattr(mesh, "corners")) {
    const auto vertices = indices_from(mesh.attr("corners"), name + ".corners");
    const auto sharpness = doubles_from(mesh.attr("corner_sharpness"), name + ".corner_sharpness");
    if (vertices.size() != sharpness.size())
      throw subdiv::Error(fmt::format("{}: {} corners but {} corner sharpness values; give one per corner", name,
                                      vertices.size(), sharpness.size()));
    for (size_t i = 0; i < vertices.size(); ++i) m.corners.push_back({vertices[i], sharpness[i]});
  }
  if (m.positions.size() % 3 != 0)
    throw subdiv::Error(fmt::format("{}: points must have 3 coordinates per vertex", name));
  subdiv::validate_mesh_data(m, name);
  return m;
}

py::dict mesh_to_python(subdiv::MeshData&& mesh) {
  py::dict out;
  const auto n = py::ssize_t(mesh.vertex_count());
  std::vector<Index> crease_pairs;
  std::vector<double> crease_sharpness;
  for (const auto& c : mesh.creases) {
    crease_pairs.push_back(c.v0), crease_pairs.push_back(c.v1);
    crease_sharpness.push_back(c.sharpness);
  }
  std::vector<Index> corners;
  std::vector<double> corner_sharpness;
  for (const auto& c : mesh.corners) corners.push_back(c.v), corner_sharpness.push_back(c.sharpness);
  const auto creases = py::ssize_t(crease_sharpness.size()), corner_count = py::ssize_t(corners.size());
  const auto corner_total = py::ssize_t(mesh.face_vertices.size()), line_total = py::ssize_t(mesh.line_vertices.size());
  const auto faces = py::ssize_t(mesh.face_offsets.size()), lines = py::ssize_t(mesh.line_offsets.size());
  out["points"] = adopt(std::move(mesh.positions), {n, 3});
  out["face_indices"] = adopt(std::move(mesh.face_vertices), {corner_total});
  out["face_offsets"] = adopt(std::move(mesh.face_offsets), {faces});
  out["line_indices"] = adopt(std::move(mesh.line_vertices), {line_total});
  out["line_offsets"] = adopt(std::move(mesh.line_offsets), {lines});
  out["creases"] = adopt(std::move(crease_pairs), {creases, 2});
  out["crease_sharpness"] = adopt(std::move(crease_sharpness), {creases});
  out["corners"] = adopt(std::move(corners), {corner_count});
  out["corner_sharpness"] = adopt(std::move(corner_sharpness), {corner_count});
  return out;
}

const char* role_name(subdiv::ArrayRole role) {
  switch (role) {
    case subdiv::ArrayRole::Normals: return "normals";
    case subdiv::ArrayRole::TextureCoordinates: return "texture_coordinates";
    case subdiv::ArrayRole::Color: return "color";
    case subdiv::ArrayRole::Data: break;
  }
  return "data";
}

subdiv::ArrayRole role_from_name(const std::string& name, const std::string& array) {
  for (auto role : {subdiv::ArrayRole::Data, subdiv::ArrayRole::Normals, subdiv::ArrayRole::TextureCoordinates,
                    subdiv::ArrayRole::Color})
    if (name == role_name(role)) return role;
  throw subdiv::Error(fmt::format("{}: role {} is not one of data, normals, texture_coordinates, color", array, subdiv::quoted(name)));
}

std::vector<subdiv::DataArray> data_arrays_from(py::handle items, Index rows, const std::string& what) {
  std::vector<subdiv::DataArray> out;
  if (items.is_none()) return out;
  for (py::handle item : items) {
    auto tuple = py::reinterpret_borrow<py::tuple>(item);
    subdiv::DataArray a;
    a.name = py::str(tuple[0]);
    auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(tuple[1]);
    if (!values) {
      PyErr_Clear();
      throw subdiv::Error(fmt::format("{} {}: cannot be read as float64 values", what, subdiv::quoted(a.name)));
    }
    if (values.ndim() < 1 || values.ndim() > 2 || values.shape(0) != rows)
      throw subdiv::Error(fmt::format("{} {}: expected {} rows (one per {}), got shape {}", what, subdiv::quoted(a.name), rows,
                                      what == "point data" ? "point" : "face",
                                      std::string(py::str(py::tuple(values.attr("shape"))))));
    a.components = values.ndim() == 2 ? int(values.shape(1)) : 1;
    a.values.assign(values.data(), values.data() + values.size());
    a.integer = tuple.size() > 2 && py::bool_(tuple[2]);
    a.role = tuple.size() > 3 ? role_from_name(py::str(tuple[3]), what + " " + subdiv::quoted(a.name)) : subdiv::ArrayRole::Data;
    out.push_back(std::move(a));
  }
  return out;
}

py::dict data_arrays_to_python(std::vector<subdiv::DataArray>&& arrays) {
  py::dict out;
  for (auto& a : arrays) {
    const auto rows = py::ssize_t(a.values.size() / size_t(std::max(a.components, 1)));
    if (a.integer) {
      std::vector<std::int32_t> whole(a.values.begin(), a.values.end());  // whole numbers that fit (mesh_data.h)
      out[py::str(a.name)] = adopt(std::move(whole), {rows, py::ssize_t(a.components)});
    } else {
      out[py::str(a.name)] = adopt(std::move(a.values), {rows, py::ssize_t(a.components)});
    }
  }
  return out;
}

py::dict roles_to_python(const std::vector<subdiv::DataArray>& arrays) {
  py::dict out;
  for (const auto& a : arrays)
    if (a.role != subdiv::ArrayRole::Data) out[py::str(a.name)] = role_name(a.role);
  return out;
}

}  // namespace subdivkit

namespace subdivkit {

std::vector<subdiv::FaceVaryingArray> face_varying_from(py::handle triples, Index corners) {
  std::vector<subdiv::FaceVaryingArray> out;
  if (triples.is_none()) return out;
  for (py::handle item : triples) {
    auto triple = py::reinterpret_borrow<py::tuple>(item);
    subdiv::FaceVaryingArray a;
    a.name = py::str(triple[0]);
    const py::array raw_indices = py::array::ensure(triple[2]);
    if (!raw_indices || (raw_indices.dtype().kind() != 'i' && raw_indices.dtype().kind() != 'u')) {
      PyErr_Clear();
      throw subdiv::Error(fmt::format("face-varying {}: corner indices must be integers, got {}", subdiv::quoted(a.name),
                                      raw_indices ? std::string(py::str(raw_indices.dtype())) : "no array"));
    }
    // Checked as 64-bit values before the int32 copy, which would wrap them.
    const auto wide = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(raw_indices);
    for (py::ssize_t i = 0; i < wide.size(); ++i)
      if (wide.data()[i] < 0 || wide.data()[i] > std::numeric_limits<std::int32_t>::max())
        throw subdiv::Error(fmt::format("face-varying {}: corner {} has index {}, out of range (0-based indices "
                                        "that fit in 32 bits)", subdiv::quoted(a.name), i, wide.data()[i]));
    auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(triple[1]);
    auto indices = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>::ensure(raw_indices);
    if (!values || !indices) {
      PyErr_Clear();
      throw subdiv::Error(fmt::format("face-varying {}: expected float64 values and integer corner indices", subdiv::quoted(a.name)));
    }
    for (py::ssize_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values.data()[i]))
        throw subdiv::Error(fmt::format("face-varying {}: value {} is {}; refinement would spread it to the "
                                        "neighbours: fill it in, or remove the array", subdiv::quoted(a.name),
                                        i / std::max<py::ssize_t>(values.ndim() == 2 ? values.shape(1) : 1, 1),
                                        values.data()[i]));
    if (values.ndim() != 2 || indices.ndim() != 1 || indices.shape(0) != corners)
      throw subdiv::Error(fmt::format("face-varying {}: expected values of shape (m, k) and {} corner indices (one "
                                      "per face corner), got shapes {} and {}", subdiv::quoted(a.name), corners,
                                      std::string(py::str(py::tuple(values.attr("shape")))),
                                      std::string(py::str(py::tuple(indices.attr("shape"))))));
    a.components = int(values.shape(1));
    a.values.assign(values.data(), values.data() + values.size());
    a.indices.assign(indices.data(), indices.data() + indices.size());
    // Named as read_mesh names OBJ's vt and vn: texture coordinates and normals.
    if (a.name == "uv" && a.components <= 3) a.role = subdiv::ArrayRole::TextureCoordinates;
    if (a.name == "normal" && a.components == 3) a.role = subdiv::ArrayRole::Normals;
    out.push_back(std::move(a));
  }
  return out;
}

py::dict face_varying_to_python(std::vector<subdiv::FaceVaryingArray>&& arrays) {
  py::dict out;
  for (auto& a : arrays) {
    const auto rows = py::ssize_t(a.values.size() / size_t(std::max(a.components, 1)));
    std::vector<std::int32_t> indices(a.indices.begin(), a.indices.end());
    const auto corners = py::ssize_t(indices.size());
    out[py::str(a.name)] = py::make_tuple(adopt(std::move(a.values), {rows, py::ssize_t(a.components)}),
                                          adopt(std::move(indices), {corners}));
  }
  return out;
}

}  // namespace subdivkit
