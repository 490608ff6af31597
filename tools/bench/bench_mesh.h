#pragma once
// Deterministic large test meshes for subdiv-bench. Every generator is a pure function of
// its arguments (no random state), so the parent process and each measurement worker
// build bit-identical meshes.
#include <cstdint>
#include <string>
#include <vector>

namespace subdiv_bench {

struct Mesh {
  std::string name;
  std::int32_t vertex_count = 0;
  std::vector<std::int32_t> face_offsets{0};  // CSR, as subdiv::build_level wants
  std::vector<std::int32_t> face_sizes;       // per face, as Far::TopologyDescriptor wants
  std::vector<std::int32_t> face_vertices;
  std::vector<double> xyz;                    // 3 doubles per vertex

  std::int32_t face_count() const { return std::int32_t(face_sizes.size()); }
};

// Mesh kinds: "torus" (regular quads, every vertex valence 4), "torus-ev" (a triangulated
// torus with every triangle split into 3 quads: valence 6 at the grid vertices, 3 at the
// triangle centres, 4 at the edge midpoints, so half the vertices are extraordinary),
// "cube-sphere" (a cube with n x n quads per side projected to the unit sphere: eight
// valence-3 vertices), "tri-torus" (the triangulated torus, all valence 6, for Loop).
// `target_faces` is approximate: the grids are rounded to whole rows.
Mesh make_mesh(const std::string& kind, std::int64_t target_faces);
std::vector<std::string> mesh_kinds();
bool mesh_is_triangles(const std::string& kind);

}  // namespace subdiv_bench
