#include "level_output.h"

#include <algorithm>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "framework/io/formats.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_seams.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/io/vtk/vtk_pieces.h"
#include "mesh_subset.h"
#include "output_options.h"
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

// The input face each face of level l lies in (-1: none; hole faces included), from level
// l - 1's (`above`; unused at level 0).
std::vector<double> base_faces_of(const Hierarchy& h, int l, const std::vector<double>& above) {
  const Level& L = h.levels[l];
  std::vector<double> base(size_t(L.face_count()));
  // On every core: 16M faces at level 2 of a 1M-face mesh, part of the writing time.
  tbb::parallel_for(tbb::blocked_range<Index>(0, L.face_count(), 1 << 16), [&](const tbb::blocked_range<Index>& r) {
    for (Index f = r.begin(); f != r.end(); ++f) {
      // Faces made around edges and vertices (dual splits) lie in no single parent face: -1.
      const Index p = l == 0 ? f : h.origins[l - 1].parent_face[f];
      base[f] = p == kNone ? -1.0 : l == 0 ? double(f) : above[p];
    }
  });
  return base;
}

// `a` at the end of `to` unless an array there has its name (the user's arrays win).
void add_unless_named(std::vector<DataArray>& to, DataArray&& a) {
  for (const DataArray& b : to)
    if (b.name == a.name) return;
  to.push_back(std::move(a));
}

// base_faces_of level l, through every level above it.
std::vector<double> base_faces_down_to(const Hierarchy& h, int l) {
  std::vector<double> base;
  for (int k = 0; k <= l; ++k) base = base_faces_of(h, k, base);
  return base;
}

// SubdivKit's arrays of level l that `arrays` asks for, added to the mesh's point and cell
// data where no user array has the name: how each vertex was made, its valence and its
// feature class; per cell, the face it lies in one level up and in the base mesh
// (`base_face`: level l's, see base_faces_of; empty unless asked for).
void add_level_arrays(const Hierarchy& h, int l, MeshData& mesh, const FeatureOptions& features,
                      std::vector<double> base_face, const ArraySelection& arrays) {
  const Level& L = h.levels[l];
  const auto add = add_unless_named;
  const size_t vertices = size_t(L.vertex_count);
  if (arrays.has("origin")) {
    DataArray origin{"origin", 1, std::vector<double>(vertices, 0.0), true};
    if (l > 0)
      for (Index v = 0; v < L.vertex_count; ++v) origin.values[v] = double(int(h.origins[l - 1].kind[v]));
    add(mesh.point_data, std::move(origin));
  }
  if (arrays.has("valence")) {
    DataArray valence{"valence", 1, std::vector<double>(vertices), true};
    for (Index v = 0; v < L.vertex_count; ++v) valence.values[v] = L.valence(v);
    add(mesh.point_data, std::move(valence));
  }
  if (arrays.has("level")) add(mesh.point_data, DataArray{"level", 1, std::vector<double>(vertices, double(l)), true});
  if (arrays.has("vertex_class")) {
    // Context's values are the documented classes: 0 smooth, 1 dart, 2 crease, 3 corner.
    DataArray vertex_class{"vertex_class", 1, std::vector<double>(vertices), true};
    const FeatureContexts fc = classify_features(L, features);
    for (Index v = 0; v < L.vertex_count; ++v) vertex_class.values[v] = double(int(fc.vertices[v].parent));
    add(mesh.point_data, std::move(vertex_class));
  }
  if (arrays.has("parent_face")) {
    DataArray parent{"parent_face", 1, std::vector<double>(size_t(L.face_count()), -1.0), true};
    if (l > 0)
      for (Index f = 0; f < L.face_count(); ++f) parent.values[f] = h.origins[l - 1].parent_face[f];
    drop_hole_tuples(L, parent);
    add(mesh.cell_data, std::move(parent));
  }
  if (arrays.has("base_face")) {
    DataArray base{"base_face", 1, std::move(base_face), true};
    drop_hole_tuples(L, base);
    add(mesh.cell_data, std::move(base));
  }
}

// Level l as a mesh with the user's arrays (moved out of `data`); hole faces and their cell
// tuples left out. With `donor` (the same level, about to go), its faces move into the mesh
// instead of being copied (320 MB on a 16M-quad level), where nothing is left out.
MeshData level_mesh(const Level& L, LevelData&& data, Level* donor = nullptr) {
  std::vector<Index> offsets, corners;
  const bool move_faces = donor == &L && L.face_hole.empty() && data.face_varying.empty();
  if (move_faces) offsets = std::move(donor->face_offsets), corners = std::move(donor->face_vertices);
  MeshData mesh = mesh_from_level(L, std::move(data.positions));  // creases and corners from its edges
  if (move_faces) mesh.face_offsets = std::move(offsets), mesh.face_vertices = std::move(corners);
  mesh.point_data = std::move(data.point_data);
  mesh.cell_data = std::move(data.cell_data);
  for (DataArray& a : mesh.cell_data) drop_hole_tuples(L, a);
  mesh.face_varying = std::move(data.face_varying);
  for (FaceVaryingArray& a : mesh.face_varying) a.indices = corners_outside_holes(L, a.indices);
  return mesh;
}

// Level l with its arrays as ParaView output, split at face-varying seams (ParaView shows
// per-point data only). The level's arrays move into the OutputLevel; `mesh` keeps the rest.
OutputLevel output_level(MeshData& mesh, int l) {
  if (!mesh.face_varying.empty()) mesh = split_at_seams(mesh);
  OutputLevel level{&mesh, l, std::move(mesh.point_data), std::move(mesh.cell_data)};
  mesh.point_data.clear(), mesh.cell_data.clear();
  return level;
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
                 std::vector<LevelData> data, const FeatureOptions& features, const std::vector<Index>& base_faces,
                 const std::vector<int>& finest_owner, int piece, const OutputChoice& choice) {
  const int finest = int(h.levels.size()) - 1;
  const Level& L = h.levels[finest];
  MeshData whole = level_mesh(L, std::move(data[finest]));
  // The arrays SubdivKit adds, base_face numbered in the whole mesh.
  std::vector<double> base_face;
  if (choice.arrays.has("base_face")) {
    base_face = base_faces_down_to(h, finest);
    for (double& b : base_face) b = b < 0 ? b : double(base_faces[size_t(b)]);
  }
  add_level_arrays(h, finest, whole, features, std::move(base_face), choice.arrays);
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
  const OutputLevel level = output_level(mine, finest);
  write_piece_vtp(staged, target, level, choice.vtk);
}

void check_output_path(const std::filesystem::path& out) {
  const std::string ext = lowercase_extension(out);
  if (ext == ".vtp" || ext == ".pvd" || ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl") return;
  throw Error(fmt::format("cannot write '{}': unknown output format '{}'; use .vtp or .pvd (ParaView), "
                          "or .obj, .off, .ply, .stl", out.string(), ext));
}

std::vector<OutputLevel> describe_levels(const Hierarchy& h, std::vector<LevelData> data,
                                         const FeatureOptions& features,
                                         const std::vector<DataArray>& finest_point_data, std::vector<MeshData>& meshes,
                                         const ArraySelection& arrays, int first, Hierarchy* consumed) {
  const int levels = int(h.levels.size());
  first = std::clamp(first, 0, levels - 1);
  meshes.clear();
  meshes.reserve(size_t(levels - first));
  std::vector<OutputLevel> out;
  std::vector<double> base_face;  // of level l, while asked for
  for (int l = 0; l < levels; ++l) {
    if (arrays.has("base_face")) base_face = base_faces_of(h, l, base_face);
    if (l < first) {
      data[l] = {};  // not written: its memory back before the finest level's output is made
      continue;
    }
    // SubdivKit's arrays first: they read the level's faces, which may move into the mesh.
    MeshData ours;
    if (l + 1 == levels) add_level_arrays(h, l, ours, features, std::move(base_face), arrays);
    else add_level_arrays(h, l, ours, features, base_face, arrays);  // the next level reads it
    meshes.push_back(level_mesh(h.levels[l], std::move(data[l]), consumed ? &consumed->levels[l] : nullptr));
    MeshData& mesh = meshes.back();
    if (l + 1 == levels)
      mesh.point_data.insert(mesh.point_data.end(), finest_point_data.begin(), finest_point_data.end());
    for (DataArray& a : ours.point_data) add_unless_named(mesh.point_data, std::move(a));
    for (DataArray& a : ours.cell_data) add_unless_named(mesh.cell_data, std::move(a));
    out.push_back(output_level(mesh, l));
  }
  return out;
}

void write_levels(const std::filesystem::path& out, Hierarchy&& h, std::vector<LevelData> data,
                  const FeatureOptions& features, const std::vector<DataArray>& finest_point_data,
                  const MeshOptions& obj_tags, const OutputChoice& choice) {
  check_output_path(out);
  const std::string ext = lowercase_extension(out);
  const int finest = int(h.levels.size()) - 1;
  if (ext != ".vtp" && ext != ".pvd") {
    MeshData mesh = level_mesh(h.levels[finest], std::move(data[finest]), &h.levels[finest]);
    mesh.point_data.insert(mesh.point_data.end(), finest_point_data.begin(), finest_point_data.end());
    mesh.options = obj_tags;
    // OBJ holds face-varying data as vt; the other formats get a point per side of a seam.
    write_mesh(out, ext == ".obj" || mesh.face_varying.empty() ? mesh : split_at_seams(mesh));
    return;
  }
  std::vector<MeshData> meshes;
  const std::vector<OutputLevel> levels = describe_levels(h, std::move(data), features, finest_point_data, meshes,
                                                          choice.arrays, ext == ".vtp" ? finest : 0, &h);
  if (ext == ".vtp") write_vtp(out, levels.back(), choice.vtk);
  else write_pvd(out, levels, choice.vtk);
}

}  // namespace subdiv::cli
