#pragma once
// Where a point of a face lies as the face is refined: OpenSubdiv Bfr's parameterisation of
// a base face (Bfr::Parameterization), and the child face of a binary primal split (quad or
// triangle) that holds the point, with the point's coordinates in that child.
//
// Bfr's parameterisation: a quad has corners (0,0), (1,0), (1,1), (0,1); a triangle (0,0),
// (1,0), (0,1); any other face of a quad split (QUAD_SUBFACES) is n sub-quads laid out on a
// grid of ceil(sqrt(n)) columns, sub-face i occupying [c, c + 1/2] x [r, r + 1/2] at column
// c = i mod columns, row r = i / columns, with its corner (0,0) at vertex i, (1,0) at the
// middle of edge i (from vertex i to i + 1), (1,1) at the face centre and (0,1) at the middle
// of edge i - 1. Each child of a split is parameterised the same way from its own corner 0.
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

using Uv = std::array<double, 2>;
// d(s, t) / d(u, v): row 0 is ds/du, ds/dv; row 1 dt/du, dt/dv.
using Jacobian = std::array<std::array<double, 2>, 2>;

// The chain rule for maps of the parameter square: d(x)/d(u, v) = A B for A = d(x)/d(s, t) and
// B = d(s, t)/d(u, v), each entry summed in the same order wherever it is used.
inline Jacobian jacobian_product(const Jacobian& A, const Jacobian& B) {
  Jacobian C{};
  for (size_t r = 0; r < 2; ++r)
    for (size_t c = 0; c < 2; ++c) C[r][c] = A[r][0] * B[0][c] + A[r][1] * B[1][c];
  return C;
}

// A point inside one face of a level, in that face's own coordinates (s, t), with the
// derivative of those coordinates with respect to the base face's (u, v).
struct FacePoint {
  Index face = kNone;
  Uv st{0, 0};
  Jacobian jacobian{{{1, 0}, {0, 1}}};
  // Set for a base face with sub-faces (an n-gon under a quad split, before its first
  // refinement): the sub-face, whose own (s, t) are st.
  int sub_face = -1;
};

// Bfr's grid width for an n-gon's sub-faces.
int sub_face_columns(int n);

// The base point (face, u, v) in the face's own terms. `triangles`: the split makes
// triangles (a face must then be a triangle). Empty when (u, v) lies outside the face's
// domain (`why` says how).
std::optional<FacePoint> base_face_point(const Level& level, Index face, double u, double v, bool triangles,
                                         const char** why);

// The corner of the face the point is at exactly, or -1.
int corner_at(const FacePoint& p, int face_size, bool triangles);

// The child faces of `p`'s face after one binary primal split, each with its corners'
// coordinates in `p`'s frame (which depends on p.sub_face only).
struct ChildFace {
  Index face = kNone;
  std::vector<Uv> corners;
};
std::vector<ChildFace> child_faces(const Level& parent, const Level& child, const ChildOrigins& origins,
                                   const FacePoint& p, bool triangles);
// Likewise among `candidates` only: the child faces whose parent is p.face, for a caller that
// has them grouped (the above scans every face of `child`).
std::vector<ChildFace> child_faces(const Level& parent, const Level& child, const ChildOrigins& origins,
                                   const FacePoint& p, bool triangles, std::span<const Index> candidates);

// The point in a child face's coordinates, or empty when the child does not hold it (up to
// eps outside its domain; the point is then clamped to the domain).
std::optional<FacePoint> point_in_child(const ChildFace& child, const FacePoint& p, bool triangles, double eps);

// The child among `children` holding the point: exactly inside first, then within 1e-12.
std::optional<FacePoint> locate(std::span<const ChildFace> children, const FacePoint& p, bool triangles, int* which);

// The child face of `p` after one binary primal split, and the point in its coordinates.
// Child vertices lie at the parent's corners (vertex children), edge middles (edge
// children) and face centres (face children). Empty when no child face holds the point
// (a split that is not binary primal).
std::optional<FacePoint> child_face_point(const Level& parent, const Level& child, const ChildOrigins& origins,
                                          const FacePoint& p, bool triangles);

}  // namespace subdiv
