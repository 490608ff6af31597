// OBJ with polylines and Pixar's tags, readable by read_mesh and by OpenSubdiv's tools;
// texture coordinates (face-varying or per vertex) as vt with their indices in the faces.
// Coordinates are printed in their shortest form that reads back to the same double.
#include <span>
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "framework/io/writers.h"
#include "framework/util/buffered_output.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {

namespace {

// One CSR list as lines "<keyword> i j k" with OBJ's 1-based numbers.
void write_lists(BufferedOutput& out, const char* keyword, std::span<const Index> offsets,
                 std::span<const Index> indices, WriteProgress* written = nullptr) {
  for (std::size_t f = 0; f + 1 < offsets.size(); ++f) {
    if (written) written->step();
    out.print("{}", keyword);
    for (Index k = offsets[f]; k < offsets[f + 1]; ++k) out.print(" {}", indices[k] + 1);
    out.print("\n");
  }
}

// The texture coordinates to write as vt: a face-varying UV array, else per-vertex UVs
// (indexed like the vertices); none when the mesh has neither.
FaceVaryingArray texture_coordinates(const MeshData& mesh) {
  for (const FaceVaryingArray& a : mesh.face_varying)
    if (a.role == ArrayRole::TextureCoordinates && a.components <= 3) return a;
  for (const DataArray& a : mesh.point_data)
    if (a.role == ArrayRole::TextureCoordinates && a.components <= 3)
      return {a.name, a.components, a.values, {mesh.face_vertices.begin(), mesh.face_vertices.end()}, a.role};
  return {};
}

void write_faces_with_uv(BufferedOutput& out, const MeshData& mesh, const std::vector<Index>& uv,
                         WriteProgress& written) {
  for (Index f = 0; f < mesh.face_count(); ++f, written.step()) {
    out.print("f");
    for (Index k = mesh.face_offsets[f]; k < mesh.face_offsets[f + 1]; ++k)
      out.print(" {}/{}", mesh.face_vertices[k] + 1, uv[k] + 1);
    out.print("\n");
  }
}

// The weights of rational control points (the point array "weight", pipeline/rational_weights.h),
// written as `v x y z w`; null when there are none.
const DataArray* rational_weights(const MeshData& mesh) {
  for (const DataArray& a : mesh.point_data)
    if (a.name == "weight" && a.components == 1 && !a.integer && a.values.size() == size_t(mesh.vertex_count())) return &a;
  return nullptr;
}

// OBJ does not say how wide its numbers are, and readers take 32-bit floats: VTK's
// vtkOBJReader reads 1e308 as 3.4e38 and -1.8e308 as 0, without a word. A number beyond
// float range is refused (SubdivKit would read it back, nothing else would).
void check_float_range(const std::vector<double>& values, int stride, const char* what, const path& shown) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (std::abs(values[i]) > double(std::numeric_limits<float>::max()))
      throw Error(fmt::format("cannot write {}: {} {} has the value {}, beyond the 32-bit float range OBJ readers "
                              "use (VTK reads it as another number); write .ply or .vtp, which store doubles",
                              subdiv::quoted(shown.string()), what, i / std::size_t(stride), values[i]));
}

}  // namespace

void write_obj(const path& file, const path& shown, const MeshData& mesh, const ProgressCallback& progress) {
  check_float_range(mesh.positions, 3, "vertex", shown);
  if (const DataArray* w = rational_weights(mesh)) check_float_range(w->values, 1, "the weight of vertex", shown);
  {
    const FaceVaryingArray uv = texture_coordinates(mesh);
    check_float_range(uv.values, std::max(uv.components, 1), "texture coordinate", shown);
  }
  BufferedOutput out(file, shown);
  out.print("# SubdivKit: {} vertices, {} faces, {} polylines\n", mesh.vertex_count(),
            mesh.face_count(), mesh.line_count());
  const std::vector<double>& p = mesh.positions;
  WriteProgress written(progress, std::size_t(mesh.vertex_count()) + std::size_t(mesh.face_count()));
  if (const DataArray* w = rational_weights(mesh))
    for (std::size_t i = 0; i < p.size(); i += 3, written.step())
      out.print("v {} {} {} {}\n", p[i], p[i + 1], p[i + 2], w->values[i / 3]);
  else
    for (std::size_t i = 0; i < p.size(); i += 3, written.step()) out.print("v {} {} {}\n", p[i], p[i + 1], p[i + 2]);
  const FaceVaryingArray uv = texture_coordinates(mesh);
  for (std::size_t i = 0; i < uv.values.size(); i += std::size_t(uv.components)) {
    out.print("vt");
    for (int c = 0; c < uv.components; ++c) out.print(" {}", uv.values[i + std::size_t(c)]);
    out.print("\n");
  }
  if (uv.indices.empty()) write_lists(out, "f", mesh.face_offsets, mesh.face_vertices, &written);
  else write_faces_with_uv(out, mesh, uv.indices, written);
  write_lists(out, "l", mesh.line_offsets, mesh.line_vertices);
  // Tags number vertices from 0, as OpenSubdiv reads them.
  for (const CreaseTag& c : mesh.creases)
    out.print("t crease 2/1/0 {} {} {}\n", c.v0, c.v1, c.sharpness);
  for (const CornerTag& c : mesh.corners) out.print("t corner 1/1/0 {} {}\n", c.v, c.sharpness);
  for (Index f : mesh.holes) out.print("t hole 1/0/0 {}\n", f);
  // The options, as OpenSubdiv's shape_utils reads them, so a round trip keeps them.
  const MeshOptions& o = mesh.options;
  if (o.interpolate_boundary) out.print("t interpolateboundary 1/0/0 {}\n", *o.interpolate_boundary);
  if (o.crease_method) out.print("t creasemethod 0/0/1 {}\n", *o.crease_method);
  if (o.smooth_triangles) out.print("t smoothtriangles 0/0/1 {}\n", *o.smooth_triangles);
  if (o.fvar_interpolate_boundary)
    out.print("t facevaryinginterpolateboundary 1/0/0 {}\n", *o.fvar_interpolate_boundary);
  if (o.fvar_propagate_corners) out.print("t facevaryingpropagatecorners 1/0/0 {}\n", *o.fvar_propagate_corners);
  out.close();
  written.finish();
}

}  // namespace subdiv::io_detail
