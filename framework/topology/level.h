#pragma once
// One mesh level as flat index arrays (the role of OpenSubdiv's Vtr::Level).
//
// Conventions
// - Faces are CCW polygons of any size, stored CSR: face f has corners
//   face_vertices[face_offsets[f] .. face_offsets[f+1]).
// - face_edges is aligned with face_vertices: corner i of f owns the edge from its
//   vertex to the next corner's vertex.
// - Edge e joins edge_vertices[2e] -> edge_vertices[2e+1]. edge_faces[2e] is the face
//   that runs the edge in that direction; edge_faces[2e+1] runs it backwards, or is
//   kNone on a boundary. So a boundary edge always has its face in slot 0.
// - Vertex rings are CCW seen from outside: ring edge i leaves v along the edge that
//   face i runs out of v, and ring face i lies between ring edges i and i+1. An interior
//   vertex has as many ring edges as ring faces; a boundary vertex has one more, and its
//   ring starts and ends on its two boundary edges.
#include <cstdint>
#include <span>
#include <vector>

namespace subdiv {

using Index = std::int32_t;
constexpr Index kNone = -1;

struct Level {
  Index vertex_count = 0;

  std::vector<Index> face_offsets{0};
  std::vector<Index> face_vertices;
  std::vector<Index> face_edges;

  std::vector<Index> edge_vertices;
  std::vector<Index> edge_faces;

  std::vector<Index> vertex_ring_offsets{0};  // CSR over vertex_edges (size n per vertex)
  std::vector<Index> vertex_edges;            // CCW ring edges
  std::vector<Index> vertex_face_offsets{0};  // CSR over vertex_faces
  std::vector<Index> vertex_faces;            // CCW ring faces
  std::vector<std::uint8_t> vertex_face_corner;  // corner of v within vertex_faces[i]
  std::vector<std::uint8_t> vertex_on_boundary;

  // Feature tags (DeRose et al. 1998 semantics): 0 smooth, >= 10 infinitely sharp.
  std::vector<float> edge_sharpness;    // empty means all smooth
  std::vector<float> vertex_sharpness;  // empty means all smooth

  Index face_count() const { return Index(face_offsets.size()) - 1; }
  Index edge_count() const { return Index(edge_vertices.size() / 2); }
  Index corner_count() const { return Index(face_vertices.size()); }
  int face_size(Index f) const { return face_offsets[f + 1] - face_offsets[f]; }
  std::span<const Index> face(Index f) const {
    return {face_vertices.data() + face_offsets[f], size_t(face_size(f))};
  }
  std::span<const Index> face_edge_list(Index f) const {
    return {face_edges.data() + face_offsets[f], size_t(face_size(f))};
  }
  // Number of ring edges: the valence.
  int valence(Index v) const { return vertex_ring_offsets[v + 1] - vertex_ring_offsets[v]; }
  std::span<const Index> ring_edges(Index v) const {
    return {vertex_edges.data() + vertex_ring_offsets[v], size_t(valence(v))};
  }
  int incident_face_count(Index v) const { return vertex_face_offsets[v + 1] - vertex_face_offsets[v]; }
  std::span<const Index> ring_faces(Index v) const {
    return {vertex_faces.data() + vertex_face_offsets[v], size_t(incident_face_count(v))};
  }
  bool edge_on_boundary(Index e) const { return edge_faces[2 * e + 1] == kNone; }
  bool on_boundary(Index v) const { return vertex_on_boundary[v] != 0; }
  // The vertex at the other end of edge e from v.
  Index other_end(Index e, Index v) const {
    return edge_vertices[2 * e] == v ? edge_vertices[2 * e + 1] : edge_vertices[2 * e];
  }
  float edge_sharp(Index e) const { return edge_sharpness.empty() ? 0.f : edge_sharpness[e]; }
  float vertex_sharp(Index v) const { return vertex_sharpness.empty() ? 0.f : vertex_sharpness[v]; }
  bool all_faces_have_size(int k) const;
  int max_face_size() const;
};

// Builds edges, face-edges and CCW vertex rings from polygons. Throws subdiv::Error naming
// the first non-manifold edge or vertex, a degenerate face, or an out-of-range index.
Level build_level(Index vertex_count, std::span<const Index> face_offsets,
                  std::span<const Index> face_vertices);

// Finds the edge joining a and b, or kNone.
Index find_edge(const Level& level, Index a, Index b);

// V - E + F, for tests and reports.
long euler_characteristic(const Level& level);

}  // namespace subdiv
