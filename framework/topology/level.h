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

#include "framework/util/scratch_vector.h"

namespace subdiv {

using Index = std::int32_t;
constexpr Index kNone = -1;
// A corner's place within its face (OpenSubdiv's Vtr::LocalIndex), so faces have at most
// kMaxFaceSize corners, as in OpenSubdiv (build_level refuses larger ones).
using LocalIndex = std::uint16_t;
constexpr int kMaxFaceSize = 65535;

// The arrays of faces, edges and rings are ScratchVectors (util/scratch_vector.h): resize()
// leaves new elements as they come, so they are first written, and their pages placed, by
// the parallel passes that fill them; whoever sizes one writes every element. The small
// arrays of marks, holes and tags (often sized, then set here and there) stay zero-filling.
struct Level {
  Index vertex_count = 0;

  ScratchVector<Index> face_offsets{0};
  ScratchVector<Index> face_vertices;
  ScratchVector<Index> face_edges;

  ScratchVector<Index> edge_vertices;
  ScratchVector<Index> edge_faces;

  ScratchVector<Index> vertex_ring_offsets{0};  // CSR over vertex_edges (size n per vertex)
  ScratchVector<Index> vertex_edges;            // CCW ring edges
  ScratchVector<Index> vertex_face_offsets{0};  // CSR over vertex_faces
  ScratchVector<Index> vertex_faces;            // CCW ring faces
  ScratchVector<LocalIndex> vertex_face_corner;  // corner of v within vertex_faces[i]
  ScratchVector<std::uint8_t> vertex_on_boundary;

  // Non-manifold topology, marked as OpenSubdiv's Vtr marks it (vtr/level.cpp,
  // completeTopologyFromFaceVertices): an edge with more than two faces, with two faces
  // that run it in the same direction (inconsistent orientation), used twice by one face or
  // joining a vertex to itself; a vertex on such an edge, or whose faces form more than one
  // fan. All empty on a manifold level (the fast path). On a non-manifold level:
  // - edge_faces holds an edge's first two faces (slot 1 kNone if it has one), and
  //   edge_face_offsets / edge_face_list (CSR) all of them;
  // - a non-manifold vertex's ring_edges and ring_faces list its edges and faces in no
  //   particular order (there is no CCW order), and vertex_on_boundary says whether one of
  //   its edges has a single face.
  // Manifold elements of a non-manifold level follow every convention above.
  std::vector<std::uint8_t> edge_non_manifold;    // per edge, or empty
  std::vector<std::uint8_t> vertex_non_manifold;  // per vertex, or empty
  std::vector<Index> edge_face_offsets;           // CSR over edge_face_list, or empty
  std::vector<Index> edge_face_list;

  // Holes (OpenSubdiv's face tag `hole`, OBJ `t hole`): faces that are refined and shape
  // their neighbours but are not part of the surface, so writers leave them out. Per face,
  // or empty when there are none.
  std::vector<std::uint8_t> face_hole;

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
  bool manifold() const { return edge_non_manifold.empty() && vertex_non_manifold.empty(); }
  bool non_manifold_edge(Index e) const { return !edge_non_manifold.empty() && edge_non_manifold[e]; }
  bool non_manifold_vertex(Index v) const { return !vertex_non_manifold.empty() && vertex_non_manifold[v]; }
  // Number of faces of edge e (any number on a non-manifold level).
  int edge_face_count(Index e) const {
    if (!edge_face_offsets.empty()) return edge_face_offsets[e + 1] - edge_face_offsets[e];
    return edge_faces[2 * e + 1] == kNone ? 1 : 2;
  }
  // All faces of edge e: a face that uses the edge twice appears twice.
  std::span<const Index> faces_of_edge(Index e) const {
    if (!edge_face_offsets.empty())
      return {edge_face_list.data() + edge_face_offsets[e], size_t(edge_face_count(e))};
    return {edge_faces.data() + 2 * e, size_t(edge_face_count(e))};
  }
  bool is_hole(Index f) const { return !face_hole.empty() && face_hole[f]; }
  bool all_faces_have_size(int k) const;
  int max_face_size() const;
  int max_valence() const;  // the largest ring (0 without vertices)
};

// Builds edges, face-edges and CCW vertex rings from polygons. Manifold input takes the
// fast path; non-manifold edges and vertices, inconsistently oriented neighbours and faces
// that repeat a vertex are marked as OpenSubdiv marks them (see above). Throws
// subdiv::Error for a face with fewer than 3 vertices or an out-of-range index.
Level build_level(Index vertex_count, std::span<const Index> face_offsets,
                  std::span<const Index> face_vertices);

// Completes a level whose faces and face-edges are known (face_offsets, face_vertices,
// face_edges, edge_vertices): edge faces, non-manifold marks and vertex rings, for levels
// that may be non-manifold. Marks given in edge_non_manifold / vertex_non_manifold (sized
// or empty) are kept, as OpenSubdiv's refinement passes them from parent to child; more
// are added where the topology shows them. If no element is non-manifold the result is an
// ordinary manifold level (the marks and edge_face_offsets / edge_face_list left empty).
void complete_general_level(Level& level);

// Finds the edge joining a and b, or kNone.
Index find_edge(const Level& level, Index a, Index b);

// V - E + F, for tests and reports.
long euler_characteristic(const Level& level);

}  // namespace subdiv
