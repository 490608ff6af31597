#include "level_output.h"

#include <algorithm>
#include <fmt/format.h>

#include "framework/io/formats.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_seams.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/io/vtk/vtk_pieces.h"
#include "mesh_subset.h"
#include "framework/util/error.h"

namespace subdiv::cli {
namespace {

// The mesh leaves hole faces out (mesh_from_level); so do its cell arrays.
void drop_hole_tuples(const Level& L, DataArray& a) {
  if (L.face_hole.empty()) return;
  const size_t c = size_t(a.components);
  size_t kept = 0;
  for (Index f = 0; f < L.face_count(); ++f)
    if (!L.is_hole(f)) std::copy_n(&a.values[size_t(f) * c], c, &a.values[kept++ * c]);
  a.values.resize(kept * c);
}

// Per-point: how each vertex was made, its valence and its feature class; per-cell: the
// face it lies in, one level up and in the base mesh.
OutputLevel describe_level(const Hierarchy& h, int l, const MeshData& mesh, const FeatureOptions& features,
                           std::vector<double>& base_face) {
  const Level& L = h.levels[l];
  OutputLevel out;
  out.mesh = &mesh;
  out.level = l;
  DataArray origin{"origin", 1, std::vector<double>(L.vertex_count, 0.0), true};
  DataArray valence{"valence", 1, std::vector<double>(L.vertex_count), true};
  DataArray level{"level", 1, std::vector<double>(L.vertex_count, double(l)), true};
  for (Index v = 0; v < L.vertex_count; ++v) valence.values[v] = L.valence(v);
  // Context's values are the documented classes: 0 smooth, 1 dart, 2 crease, 3 corner.
  DataArray vertex_class{"vertex_class", 1, std::vector<double>(L.vertex_count), true};
  const FeatureContexts fc = classify_features(L, features);
  for (Index v = 0; v < L.vertex_count; ++v) vertex_class.values[v] = double(int(fc.vertices[v].parent));
  DataArray parent{"parent_face", 1, std::vector<double>(L.face_count(), -1.0), true};
  std::vector<double> next_base(L.face_count());
  for (Index f = 0; f < L.face_count(); ++f) next_base[f] = f;
  if (l > 0) {
    const ChildOrigins& o = h.origins[l - 1];
    for (Index v = 0; v < L.vertex_count; ++v) origin.values[v] = double(int(o.kind[v]));
    // Faces made around edges and vertices (dual splits) lie in no single parent face: -1.
    for (Index f = 0; f < L.face_count(); ++f) {
      const Index p = o.parent_face[f];
      parent.values[f] = p;
      next_base[f] = p == kNone ? -1.0 : base_face[p];
    }
  }
  base_face = std::move(next_base);
  DataArray base{"base_face", 1, base_face, true};
  drop_hole_tuples(L, parent);
  drop_hole_tuples(L, base);
  // The user's arrays (already in the mesh) first; SubdivKit's where no user array has the name.
  out.point_data = mesh.point_data;
  out.cell_data = mesh.cell_data;
  auto add = [](std::vector<DataArray>& to, DataArray&& a) {
    for (const DataArray& b : to)
      if (b.name == a.name) return;
    to.push_back(std::move(a));
  };
  for (DataArray* a : {&origin, &valence, &level, &vertex_class}) add(out.point_data, std::move(*a));
  for (DataArray* a : {&parent, &base}) add(out.cell_data, std::move(*a));
  return out;
}

// Level l as a mesh with the user's arrays; hole faces and their cell tuples left out.
MeshData level_mesh(const Level& L, const LevelData& data) {
  MeshData mesh = mesh_from_level(L, data.positions);
  mesh.point_data = data.point_data;
  mesh.cell_data = data.cell_data;
  for (DataArray& a : mesh.cell_data) drop_hole_tuples(L, a);
  mesh.face_varying = data.face_varying;
  for (FaceVaryingArray& a : mesh.face_varying) a.indices = corners_outside_holes(L, a.indices);
  return mesh;
}

// Level by level: the mesh with the user's arrays (hole faces left out), the finest with
// finest_point_data added.
std::vector<MeshData> level_meshes(const Hierarchy& h, const std::vector<LevelData>& data,
                                   const std::vector<DataArray>& finest_point_data) {
  std::vector<MeshData> meshes;
  meshes.reserve(h.levels.size());
  for (size_t l = 0; l < h.levels.size(); ++l) meshes.push_back(level_mesh(h.levels[l], data[l]));
  for (const auto& a : finest_point_data) meshes.back().point_data.push_back(a);
  return meshes;
}

// The faces of `mesh` at `kept` with the vertices they use, in their old order.
MeshData keep_faces(const MeshData& mesh, const std::vector<Index>& kept, std::vector<Index>& new_vertex) {
  new_vertex.assign(mesh.vertex_count(), kNone);
  for (Index f : kept)
    for (Index i = mesh.face_offsets[f]; i < mesh.face_offsets[f + 1]; ++i) new_vertex[mesh.face_vertices[i]] = 0;
  std::vector<Index> used;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (new_vertex[v] == 0) new_vertex[v] = Index(used.size()), used.push_back(v);
  return mesh_subset(mesh, used, kept, new_vertex);
}

}  // namespace

void write_piece(StagedFiles& staged, const std::filesystem::path& target, const Hierarchy& h,
                 const std::vector<LevelData>& data, const FeatureOptions& features,
                 const std::vector<Index>& base_faces, const std::vector<int>& finest_owner, int piece) {
  const int finest = int(h.levels.size()) - 1;
  const Level& L = h.levels[finest];
  MeshData whole = level_mesh(L, data[finest]);
  // The arrays SubdivKit adds, base_face through every level, then numbered in the whole mesh.
  std::vector<double> base_face;
  const MeshData none;
  for (int l = 0; l < finest; ++l) describe_level(h, l, none, features, base_face);
  OutputLevel described = describe_level(h, finest, whole, features, base_face);
  for (DataArray& a : described.cell_data)
    if (a.name == "base_face")
      for (double& b : a.values) b = b < 0 ? b : double(base_faces[size_t(b)]);
  whole.point_data = std::move(described.point_data);
  whole.cell_data = std::move(described.cell_data);
  // The piece's own faces, numbered as `whole` numbers them (holes left out).
  std::vector<Index> kept;
  for (Index f = 0, written = 0; f < L.face_count(); ++f) {
    if (L.is_hole(f)) continue;
    if (finest_owner[f] == piece) kept.push_back(written);
    ++written;
  }
  std::vector<Index> new_vertex;
  MeshData mine = keep_faces(whole, kept, new_vertex);
  for (const CreaseTag& c : whole.creases) {
    const Index e = find_edge(L, c.v0, c.v1);
    if (e != kNone && finest_owner[L.edge_faces[2 * e]] == piece && new_vertex[c.v0] != kNone && new_vertex[c.v1] != kNone)
      mine.creases.push_back({new_vertex[c.v0], new_vertex[c.v1], c.sharpness});
  }
  mine = split_at_seams(mine);  // ParaView shows per-point data only
  OutputLevel level{&mine, finest, std::move(mine.point_data), std::move(mine.cell_data)};
  mine.point_data.clear(), mine.cell_data.clear();
  write_piece_vtp(staged, target, level);
}

void check_output_path(const std::filesystem::path& out) {
  const std::string ext = lowercase_extension(out);
  if (ext == ".vtp" || ext == ".pvd" || ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl") return;
  throw Error(fmt::format("cannot write '{}': unknown output format '{}'; use .vtp or .pvd (ParaView), "
                          "or .obj, .off, .ply, .stl", out.string(), ext));
}

std::vector<OutputLevel> describe_levels(const Hierarchy& h, const std::vector<LevelData>& data,
                                         const FeatureOptions& features,
                                         const std::vector<DataArray>& finest_point_data,
                                         std::vector<MeshData>& meshes) {
  meshes = level_meshes(h, data, finest_point_data);
  std::vector<OutputLevel> levels;
  std::vector<double> base_face;
  for (int l = 0; l < int(meshes.size()); ++l) {
    const OutputLevel described = describe_level(h, l, meshes[l], features, base_face);
    meshes[l].point_data = described.point_data;
    meshes[l].cell_data = described.cell_data;
    meshes[l] = split_at_seams(meshes[l]);  // ParaView shows per-point data only
    OutputLevel level{&meshes[l], l, std::move(meshes[l].point_data), std::move(meshes[l].cell_data)};
    meshes[l].point_data.clear(), meshes[l].cell_data.clear();
    levels.push_back(std::move(level));
  }
  return levels;
}

void write_levels(const std::filesystem::path& out, const Hierarchy& h, const std::vector<LevelData>& data,
                  const FeatureOptions& features, const std::vector<DataArray>& finest_point_data,
                  const MeshOptions& obj_tags) {
  check_output_path(out);
  const std::string ext = lowercase_extension(out);
  if (ext != ".vtp" && ext != ".pvd") {
    MeshData finest = std::move(level_meshes(h, data, finest_point_data).back());
    finest.options = obj_tags;
    // OBJ holds face-varying data as vt; the other formats get a point per side of a seam.
    write_mesh(out, ext == ".obj" ? finest : split_at_seams(finest));
    return;
  }
  std::vector<MeshData> meshes;
  const std::vector<OutputLevel> levels = describe_levels(h, data, features, finest_point_data, meshes);
  if (ext == ".vtp") write_vtp(out, levels.back());
  else write_pvd(out, levels);
}

}  // namespace subdiv::cli
