#pragma once
// The quad mesh that Loop & Schaefer's patches are built on (limit/bezier_approximation.h),
// walked around its vertices: each face corner lies in a sector of faces around its vertex,
// bounded by boundary or infinitely sharp edges (or closed around an interior vertex), and
// the masks the patches take at that corner depend on the sector. Private to the limit
// layer.
#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/topology/level.h"

namespace subdiv::bezier {

using Point3 = std::array<double, 3>;

inline Point3 operator+(const Point3& a, const Point3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Point3 operator-(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Point3 operator*(double s, const Point3& a) { return {s * a[0], s * a[1], s * a[2]}; }

// The faces around a vertex between two feature edges, in walk order f_0 .. f_(faces-1):
// f_j lies between the edges to neighbours E_j and E_(j+1) (E_0 and E_faces the feature
// edges), f_(j+1) is across E_(j+1) from f_j. Around an interior vertex without feature
// edges the sector is closed and holds all `faces` of the vertex.
struct Sector {
  int faces = 0;
  int index = 0;  // the corner's face is f_index: its edge to the next corner is E_index
  bool closed = false;
  bool corner = false;  // the vertex is kept as a corner (its limit is itself)
  // The sector's angle in the patches' parameter plane: 2 pi closed, pi on a boundary or
  // crease; at a corner pi / 2 (convex) or 3 pi / 2 (concave), as Biermann, Levin & Zorin
  // (2000) take corners, chosen by the control mesh's angle at the vertex (the sum of its
  // faces' angles there below or above pi).
  double angle = 0;
};

// cos(2 pi / n) at an interior vertex of valence n, cos(pi / k) on a boundary or crease with
// k faces on the side, cos(angle / k) at a corner of k faces: the factor in t_(i-1) + t_(i+1) = 2 c t_i between the tangents along
// consecutive edges of the sector (0 where the sector is regular), which the tangent patches
// (Loop & Schaefer 2008) and the Gregory patches' face points (Loop, Schaefer, Ni & Castaño
// 2009) rely on.
double tangent_cosine(const Sector& s);

class QuadMesh;

// Loop & Schaefer's (2008) interior point next to corner k of face f:
// (n v + 2 e_a + 2 e_b + d) / (n + 5), e_a and e_b v's neighbours in the quad, d the opposite
// corner, n v's valence inside the surface (mask_valence elsewhere).
Point3 interior_point(const QuadMesh& m, Index f, int k);

class QuadMesh {
public:
  // Throws subdiv::Error naming the face for a face that is not a quad, a non-manifold or
  // inconsistently oriented edge, a semi-sharp edge or vertex, a smooth feature vertex with
  // one face on a side, or a corner inside the surface — the cases the masks do not cover. A dart (one feature edge at a vertex) is a smooth
  // vertex, its sector closed.
  // `normals`: the limit's unit normal per vertex (xyz; zero where none), onto whose plane
  // the corner tangents of vertices with one tangent plane are projected; may be empty.
  QuadMesh(const Level& level, std::span<const double> positions, BoundaryInterpolation boundary,
           std::span<const double> normals = {});

  Index vertex(Index f, int k) const {
    return level_.face_vertices[size_t(level_.face_offsets[size_t(f)]) + size_t(((k % 4) + 4) % 4)];
  }
  Point3 point(Index v) const {
    const size_t i = 3 * size_t(v);
    return {positions_[i], positions_[i + 1], positions_[i + 2]};
  }
  // Whether edge k of face f (corner k to k + 1) is a boundary or infinitely sharp edge.
  bool feature(Index f, int k) const;
  // Whether the edge from corner k of f towards corner k + 1 (towards_next) or k - 1 is a
  // feature curve at that corner: a feature edge whose corner is not a dart. (The Gregory
  // patches take a dart's edge points as a smooth vertex's on every edge, the crease's too,
  // so that its tangents keep the ring's relation the face points rely on.)
  bool curve_at(Index f, int k, bool towards_next) const {
    return feature(f, towards_next ? k : k + 3) && !sector(f, k).closed;
  }
  // The face and corner where the directed edge a -> b starts (the edge must exist).
  std::pair<Index, int> face_of(Index a, Index b) const { return edge_.at(key(a, b)); }
  const Sector& sector(Index f, int k) const { return sectors_[4 * size_t(f) + size_t(((k % 4) + 4) % 4)]; }

  // The limit tangent at corner k of face f along its edge to corner k + 1 (towards_next)
  // or k - 1, for the patch parameter of unit speed where the sector is regular; projected
  // onto the vertex's tangent plane where it has one (interior and boundary vertices).
  Point3 corner_tangent(Index f, int k, bool towards_next) const;

  // The face across the edge from corner k of f to corner k - 1 (one step in walk order), and
  // the corner of the same vertex in it.
  std::pair<Index, int> step_forward(Index f, int k) const { return face_of(vertex(f, k), vertex(f, k + 3)); }
  // t minus its component along v's limit normal (t unchanged where there is none).
  Point3 projected(Index v, const Point3& t) const;

private:
  static std::uint64_t key(Index a, Index b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }
  bool has_edge(Index a, Index b) const { return edge_.contains(key(a, b)); }
  void find_sectors();  // fills sectors_, refusing what the masks do not cover
  Sector find_sector(Index f, int k) const;
  // Across the edge to corner k + 1 (one step back in walk order).
  std::pair<Index, int> step_back(Index f, int k) const;
  Point3 mask_tangent(Index f, int k, bool towards_next, const Sector& s) const;
  // The tangent along E_j of a corner's sector whose first face (f_0) has v at first_corner.
  Point3 corner_sector_tangent(Index first_face, int first_corner, const Sector& s, int j) const;

  const Level& level_;
  std::span<const double> positions_;
  BoundaryInterpolation boundary_;
  std::span<const double> normals_;
  std::unordered_map<std::uint64_t, std::pair<Index, int>> edge_;
  std::vector<Sector> sectors_;  // per face corner, 4 f + k
};

}  // namespace subdiv::bezier
