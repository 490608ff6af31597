#include "framework/pipeline/level_description.h"

#include <algorithm>
#include <tbb/parallel_for.h>

#include "framework/features/feature_context.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_seams.h"

namespace subdiv {
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

// `a` at the end of `to` unless an array there has its name (the user's arrays win).
void add_unless_named(std::vector<DataArray>& to, DataArray&& a) {
  for (const DataArray& b : to)
    if (b.name == a.name) return;
  to.push_back(std::move(a));
}

}  // namespace

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

std::vector<double> base_faces_down_to(const Hierarchy& h, int l) {
  std::vector<double> base;
  for (int k = 0; k <= l; ++k) base = base_faces_of(h, k, base);
  return base;
}

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

MeshData level_mesh(const Level& L, LevelData&& data, Level* donor) {
  ScratchVector<Index> offsets, corners;
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

MeshData described_level_mesh(const Hierarchy& h, int l, LevelData&& data, const FeatureOptions& features,
                              std::vector<double> base_face, const ArraySelection& arrays,
                              const std::vector<DataArray>& extra_point_data, Level* donor) {
  // SubdivKit's arrays first: they read the level's faces, which may move into the mesh.
  MeshData ours;
  add_level_arrays(h, l, ours, features, std::move(base_face), arrays);
  MeshData mesh = level_mesh(h.levels[l], std::move(data), donor);
  mesh.point_data.insert(mesh.point_data.end(), extra_point_data.begin(), extra_point_data.end());
  for (DataArray& a : ours.point_data) add_unless_named(mesh.point_data, std::move(a));
  for (DataArray& a : ours.cell_data) add_unless_named(mesh.cell_data, std::move(a));
  return mesh;
}

OutputLevel output_level(MeshData& mesh, int l) {
  if (!mesh.face_varying.empty()) mesh = split_at_seams(mesh);
  OutputLevel level{&mesh, l, std::move(mesh.point_data), std::move(mesh.cell_data)};
  mesh.point_data.clear(), mesh.cell_data.clear();
  return level;
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
    const bool finest = l + 1 == levels;
    meshes.push_back(described_level_mesh(h, l, std::move(data[l]), features,
                                          finest ? std::move(base_face) : base_face,  // the next level reads it
                                          arrays, finest ? finest_point_data : std::vector<DataArray>{},
                                          consumed ? &consumed->levels[l] : nullptr));
    out.push_back(output_level(meshes.back(), l));
  }
  return out;
}

}  // namespace subdiv
