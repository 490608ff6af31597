#pragma once
// Test meshes and a piecewise refinement for the pieces tests: a bumpy open sheet with
// extraordinary vertices, an infinitely sharp and a semi-sharp crease, a corner and a hole.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include "framework/engine/mesh_pieces.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "support/test_meshes.h"

namespace subdiv::test {

// An (n x n) sheet, z bumped so that no two refined points coincide. Quads, with every third
// quad of a row cut into two triangles (valences 3 to 6), or all cut on alternating
// diagonals for triangle schemes (valences 4 to 8).
inline Mesh bumpy_sheet(int n, bool triangles) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.add_vertex(i + 0.1 * std::sin(3.0 * j), j, 0.3 * std::sin(1.7 * i + 2.3 * j * j));
  auto id = [&](int i, int j) { return Index(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      const bool cut = triangles || (i + 2 * j) % 3 == 0;
      if (!cut) m.add_face({a, b, c, d});
      else if ((i + j) % 2) m.add_face({a, b, c}), m.add_face({a, c, d});
      else m.add_face({a, b, d}), m.add_face({b, c, d});
    }
  return m;
}

// The sheet's level with features: row j = n/2 an infinitely sharp crease, column i = n/3
// a crease of sharpness 1.5, a corner where they cross, and one hole face.
inline Level featured_level(const Mesh& m, int n) {
  Level L = m.level();
  L.edge_sharpness.assign(L.edge_count(), 0.f);
  auto id = [&](int i, int j) { return Index(j * (n + 1) + i); };
  for (int i = 0; i < n; ++i) {
    if (Index e = find_edge(L, id(i, n / 2), id(i + 1, n / 2)); e != kNone) L.edge_sharpness[e] = 10.f;
    if (Index e = find_edge(L, id(n / 3, i), id(n / 3, i + 1)); e != kNone) L.edge_sharpness[e] = 1.5f;
  }
  L.vertex_sharpness.assign(L.vertex_count, 0.f);
  L.vertex_sharpness[id(n / 3, n / 2)] = 10.f;
  L.face_hole.assign(L.face_count(), 0);
  L.face_hole[L.face_count() / 3] = 1;
  return L;
}

using Point = std::array<std::uint64_t, 3>;  // a position's bits: equal means bit for bit equal
using Face = std::vector<Point>;             // from its smallest point, in its order

inline Face canonical_face(std::vector<Point> f) {
  std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return f;
}

// The refined surface as a sorted list of faces (holes left out): two refinements are the
// same surface, up to renumbering, when their lists are equal.
inline void add_faces(const Level& L, const std::vector<double>& p, const std::vector<int>* owner, int piece,
                      std::vector<Face>& out) {
  for (Index f = 0; f < L.face_count(); ++f) {
    if (L.is_hole(f) || (owner && (*owner)[f] != piece)) continue;
    std::vector<Point> face;
    for (Index v : L.face(f))
      face.push_back({std::bit_cast<std::uint64_t>(p[3 * v]), std::bit_cast<std::uint64_t>(p[3 * v + 1]),
                      std::bit_cast<std::uint64_t>(p[3 * v + 2])});
    out.push_back(canonical_face(std::move(face)));
  }
}

inline std::vector<double> refine_positions(const Scheme& s, const Hierarchy& h, std::vector<double> p,
                                            const RefineOptions& o) {
  for (int l = 0; l + 1 < int(h.levels.size()); ++l) p = step_values(s, h, l, p, 3, o);
  return p;
}

inline std::vector<Face> serial_faces(const Scheme& s, const Level& base, const std::vector<double>& positions,
                                      const RefineOptions& o) {
  const Hierarchy h = refine_topology(s, base, o);
  std::vector<Face> faces;
  add_faces(h.levels.back(), refine_positions(s, h, positions, o), nullptr, 0, faces);
  std::sort(faces.begin(), faces.end());
  return faces;
}

// Every piece refined on its own with `rings` ghost rings, the faces it owns merged.
inline std::vector<Face> merged_pieces(const Scheme& s, const Level& base, const std::vector<double>& positions,
                                       const std::vector<int>& owner, int pieces, int rings, const RefineOptions& o) {
  std::vector<Face> faces;
  for (int piece = 0; piece < pieces; ++piece) {
    const MeshPiece cut = cut_piece(base, owner, piece, rings);
    const Hierarchy h = refine_topology(s, cut.level, o);
    const std::vector<int> kept = finest_face_owners(h, cut.face_owner);
    add_faces(h.levels.back(), refine_positions(s, h, gather_tuples(positions, 3, cut.base_vertex), o), &kept, piece,
              faces);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

}  // namespace subdiv::test
