#include "framework/io/mesh_level.h"

#include <cmath>
#include <fmt/format.h>

#include "framework/util/error.h"

namespace subdiv {
namespace {

void check_positions(const MeshData& mesh, const std::string& source) {
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!std::isfinite(mesh.positions[i]))
      throw Error(fmt::format("{}: vertex {} has a non-finite coordinate ({}); fix or remove it",
                              source, i / 3, mesh.positions[i]));
}

void apply_creases(const MeshData& mesh, Level& level, const std::string& source) {
  if (mesh.creases.empty()) return;
  level.edge_sharpness.assign(level.edge_count(), 0.f);
  for (size_t i = 0; i < mesh.creases.size(); ++i) {
    const CreaseTag& c = mesh.creases[i];
    if (!(c.sharpness >= 0))
      throw Error(fmt::format("{}: crease {} ({} {}) has sharpness {}; sharpness must be >= 0",
                              source, i, c.v0, c.v1, c.sharpness));
    const bool in_range = c.v0 >= 0 && c.v1 >= 0 && c.v0 < level.vertex_count && c.v1 < level.vertex_count;
    const Index e = in_range ? find_edge(level, c.v0, c.v1) : kNone;
    if (e == kNone)
      throw Error(fmt::format("{}: crease {} names the edge ({}, {}), which is not an edge of the "
                              "mesh; crease tags must name two vertices joined by an edge (0-based)",
                              source, i, c.v0, c.v1));
    level.edge_sharpness[e] = float(c.sharpness);
  }
}

void apply_corners(const MeshData& mesh, Level& level, const std::string& source) {
  if (mesh.corners.empty()) return;
  level.vertex_sharpness.assign(level.vertex_count, 0.f);
  for (size_t i = 0; i < mesh.corners.size(); ++i) {
    const CornerTag& c = mesh.corners[i];
    if (c.v < 0 || c.v >= level.vertex_count)
      throw Error(fmt::format("{}: corner {} names vertex {}, but the mesh has {} vertices", source,
                              i, c.v, level.vertex_count));
    if (!(c.sharpness >= 0))
      throw Error(fmt::format("{}: corner {} (vertex {}) has sharpness {}; sharpness must be >= 0",
                              source, i, c.v, c.sharpness));
    level.vertex_sharpness[c.v] = float(c.sharpness);
  }
}

void apply_holes(const MeshData& mesh, Level& level, const std::string& source) {
  if (mesh.holes.empty()) return;
  level.face_hole.assign(level.face_count(), 0);
  for (size_t i = 0; i < mesh.holes.size(); ++i) {
    const Index f = mesh.holes[i];
    if (f < 0 || f >= level.face_count())
      throw Error(fmt::format("{}: hole {} names face {}, but the mesh has {} faces (holes number faces from 0)",
                              source, i, f, level.face_count()));
    level.face_hole[f] = 1;
  }
  require_some_face_outside_holes(level, source);
}

}  // namespace

void require_some_face_outside_holes(const Level& level, const std::string& source) {
  if (level.face_hole.empty() || level.face_count() == 0) return;
  for (Index f = 0; f < level.face_count(); ++f)
    if (!level.face_hole[f]) return;
  throw Error(fmt::format("{}: all {} faces are holes, so nothing is left to refine or write; remove at least one "
                          "hole tag",
                          source, level.face_count()));
}

Level level_from_mesh(const MeshData& mesh, const std::string& source) {
  check_positions(mesh, source);
  Level level;
  try {
    level = build_level(mesh.vertex_count(), mesh.face_offsets, mesh.face_vertices);
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", source, e.what()));
  }
  apply_creases(mesh, level, source);
  apply_corners(mesh, level, source);
  apply_holes(mesh, level, source);
  return level;
}

MeshData mesh_from_level(const Level& level, std::vector<double> positions) {
  MeshData mesh;
  mesh.positions = std::move(positions);
  if (level.face_hole.empty()) {
    mesh.face_offsets = level.face_offsets;
    mesh.face_vertices = level.face_vertices;
  } else {
    // Holes are not part of the surface (OpenSubdiv's hole tag): left out.
    for (Index f = 0; f < level.face_count(); ++f) {
      if (level.is_hole(f)) continue;
      const auto corners = level.face(f);
      mesh.face_vertices.insert(mesh.face_vertices.end(), corners.begin(), corners.end());
      mesh.face_offsets.push_back(Index(mesh.face_vertices.size()));
    }
  }
  for (Index e = 0; e < Index(level.edge_sharpness.size()); ++e)
    if (level.edge_sharpness[e] > 0.f && !level.edge_on_boundary(e))  // boundaries are sharp anyway
      mesh.creases.push_back({level.edge_vertices[2 * e], level.edge_vertices[2 * e + 1], level.edge_sharpness[e]});
  for (Index v = 0; v < Index(level.vertex_sharpness.size()); ++v)
    if (level.vertex_sharpness[v] > 0.f) mesh.corners.push_back({v, level.vertex_sharpness[v]});
  return mesh;
}

std::vector<Index> corners_outside_holes(const Level& level, const std::vector<Index>& per_corner) {
  if (level.face_hole.empty()) return per_corner;
  std::vector<Index> kept;
  for (Index f = 0; f < level.face_count(); ++f)
    if (!level.is_hole(f))
      kept.insert(kept.end(), per_corner.begin() + level.face_offsets[f], per_corner.begin() + level.face_offsets[f + 1]);
  return kept;
}

}  // namespace subdiv
