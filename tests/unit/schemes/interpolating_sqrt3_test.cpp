// Interpolating sqrt(3) (Labsik & Greiner 2000, "Interpolatory sqrt(3)-subdivision",
// Computer Graphics Forum 19(3)): Kobbelt's sqrt(3) topology, old vertices kept, and a new
// point in every triangle:
//   regular (three interior vertices of valence 6): 32/81 on the face's vertices, -1/81 on
//   the three tips (the vertices of the neighbouring triangles across the face's edges),
//   -2/81 on the six outer vertices (across the other two edges of each tip triangle);
//   otherwise the mean over the face's extraordinary vertices of their valence-K stencil:
//   a = (2/3) cos(pi/K), the vertex 1 - a^2, ring vertex j (counted from the face's previous
//   vertex) (a^2 + 2a cos((2j+1) pi/K) + 2a^2 cos((4j+2) pi/K)) / K; K = 3: (4/27, -5/27, 4/27).
// Boundaries: cubic Lagrange trisection (-5/81, 20/27, 10/27, -4/81) every second step.
// Every expected value below is one of these formulas, or OpenMesh's InterpolatingSqrt3LGT
// (Debian's libopenmesh-dev), an independent implementation of the paper, on closed meshes.
#include <doctest/doctest.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3InterpolatingSubdividerLabsikGreinerT.hh>
#include <algorithm>
#include <cmath>
#include <map>

#include "framework/scheme/scheme_validator.h"
#include "support/refine_helpers.h"

using namespace subdiv;

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
};
using OmMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

test::Mesh tetrahedron() {
  test::Mesh m;
  m.add_vertex(0, 0, 0), m.add_vertex(1, 0.1, 0), m.add_vertex(0.2, 1, 0), m.add_vertex(0.3, 0.2, 1.1);
  m.add_face({0, 2, 1}), m.add_face({0, 1, 3}), m.add_face({1, 2, 3}), m.add_face({0, 3, 2});
  return m;
}

// Moves every vertex a little, so that no symmetry hides a wrong weight.
test::Mesh perturbed(test::Mesh m) {
  for (size_t i = 0; i < m.positions.size(); ++i) m.positions[i] += 0.05 * std::sin(1.7 * double(i) + 0.3);
  return m;
}

std::vector<double> openmesh_refine(const test::Mesh& m, int levels) {
  OmMesh om;
  std::vector<OmMesh::VertexHandle> vh;
  for (Index v = 0; v < m.vertex_count; ++v)
    vh.push_back(om.add_vertex(OmMesh::Point(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2])));
  for (size_t f = 0; f + 1 < m.offsets.size(); ++f) {
    std::vector<OmMesh::VertexHandle> face;
    for (Index c = m.offsets[f]; c < m.offsets[f + 1]; ++c) face.push_back(vh[size_t(m.corners[c])]);
    om.add_face(face);
  }
  OpenMesh::Subdivider::Uniform::InterpolatingSqrt3LGT<OmMesh> subdivider;
  subdivider.attach(om);
  subdivider(size_t(levels));
  subdivider.detach();
  std::vector<double> out;
  for (auto v : om.vertices())
    for (int d = 0; d < 3; ++d) out.push_back(om.point(v)[d]);
  return out;
}

// The largest distance from a point of `a` to the nearest point of `b` (the two libraries
// number the vertices of later levels differently).
double set_distance(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0;
  for (size_t i = 0; i < a.size(); i += 3) {
    double best = 1e300;
    for (size_t k = 0; k < b.size(); k += 3)
      best = std::min(best, std::hypot(a[i] - b[k], a[i + 1] - b[k + 1], a[i + 2] - b[k + 2]));
    worst = std::max(worst, best);
  }
  return worst;
}

// The vertex of the face across edge (p, q) from r.
Index across(const Level& L, Index p, Index q, Index r) {
  const Index e = find_edge(L, p, q);
  for (int s = 0; s < 2; ++s) {
    const Index f = L.edge_faces[2 * e + s];
    if (f == kNone) continue;
    const auto fv = L.face(f);
    if (std::find(fv.begin(), fv.end(), r) != fv.end()) continue;
    for (Index u : fv)
      if (u != p && u != q) return u;
  }
  return kNone;
}

std::map<Index, double> row_of(const StencilTable& t, Index r) {
  std::map<Index, double> row;
  for (Index i = t.offsets[r]; i < t.offsets[r + 1]; ++i) row[t.indices[i]] += t.weights[i];
  return row;
}

void check_row(const std::map<Index, double>& got, const std::map<Index, double>& want) {
  for (const auto& entry : want) {
    const auto it = got.find(entry.first);
    CAPTURE(entry.first);
    REQUIRE(it != got.end());
    CHECK(it->second == doctest::Approx(entry.second).epsilon(1e-13));
  }
  for (const auto& entry : got)
    if (!want.count(entry.first)) CHECK(std::abs(entry.second) < 1e-14);
}

}  // namespace

TEST_CASE("interpolating sqrt3: the regular 12-point face stencil (Labsik & Greiner 2000)") {
  const test::Mesh m = perturbed(test::torus(8, 6, true));
  const test::Refined r = test::refine_mesh(m, "interpolating-sqrt3", 1);
  const Level& L = r.hierarchy.levels[0];
  for (Index v = 0; v < L.vertex_count; ++v) REQUIRE(L.valence(v) == 6);
  for (Index f = 0; f < L.face_count(); ++f) {
    std::map<Index, double> want;
    const auto fv = L.face(f);
    for (int i = 0; i < 3; ++i) {
      const Index p = fv[i], q = fv[(i + 1) % 3], o = fv[(i + 2) % 3];
      want[p] += 32.0 / 81;
      const Index tip = across(L, p, q, o);
      want[tip] -= 1.0 / 81;
      want[across(L, q, tip, p)] -= 2.0 / 81;  // across the tip triangle's other two edges
      want[across(L, tip, p, q)] -= 2.0 / 81;
    }
    CAPTURE(f);
    check_row(row_of(r.hierarchy.stencils[0], L.vertex_count + f), want);
  }
}

TEST_CASE("interpolating sqrt3: valence 3 and 4 stencils (Labsik & Greiner 2000)") {
  SUBCASE("tetrahedron, every vertex of valence 3: 32/81 on the face, -15/81 on the apex") {
    // Each corner: 8/9 itself, 4/27 on the face's other two vertices, -5/27 on the apex; the
    // face point is the mean of the three.
    const test::Mesh m = tetrahedron();
    const test::Refined r = test::refine_mesh(m, "interpolating-sqrt3", 1);
    const Level& L = r.hierarchy.levels[0];
    for (Index f = 0; f < L.face_count(); ++f) {
      std::map<Index, double> want;
      for (Index v = 0; v < 4; ++v) want[v] = -15.0 / 81;
      for (Index v : L.face(f)) want[v] = 32.0 / 81;
      check_row(row_of(r.hierarchy.stencils[0], L.vertex_count + f), want);
    }
  }
  SUBCASE("octahedron, every vertex of valence 4: 11/27 on the face, -2/27 on the others") {
    // Each corner: 7/9 itself, 2/9 on the face's other two vertices, -1/9 on its other two
    // ring vertices; every vertex off the face lies in the rings of two of its corners.
    const test::Mesh m = test::octahedron();
    const test::Refined r = test::refine_mesh(m, "interpolating-sqrt3", 1);
    const Level& L = r.hierarchy.levels[0];
    for (Index f = 0; f < L.face_count(); ++f) {
      std::map<Index, double> want;
      for (Index v = 0; v < 6; ++v) want[v] = -2.0 / 27;
      for (Index v : L.face(f)) want[v] = 11.0 / 27;
      check_row(row_of(r.hierarchy.stencils[0], L.vertex_count + f), want);
    }
  }
}

TEST_CASE("interpolating sqrt3 equals OpenMesh's InterpolatingSqrt3LGT on closed meshes") {
  const std::vector<std::pair<const char*, test::Mesh>> meshes = {
      {"tetrahedron", tetrahedron()},
      {"octahedron", perturbed(test::octahedron())},
      {"bipyramid 5", perturbed(test::bipyramid(5))},
      {"bipyramid 7", perturbed(test::bipyramid(7))},
      {"torus", perturbed(test::torus(6, 5, true))},
  };
  for (const auto& named : meshes) {
    const char* name = named.first;
    CAPTURE(name);
    for (int levels = 1; levels <= 3; ++levels) {
      CAPTURE(levels);
      const test::Refined ours = test::refine_mesh(named.second, "interpolating-sqrt3", levels);
      const std::vector<double> theirs = openmesh_refine(named.second, levels);
      REQUIRE(ours.positions.size() == theirs.size());
      if (levels == 1)  // the same numbering: old vertices, then one per face in face order
        for (size_t i = 0; i < theirs.size(); ++i) CHECK(ours.positions[i] == doctest::Approx(theirs[i]).epsilon(1e-12));
      CHECK(set_distance(ours.positions, theirs) < 1e-12);
      CHECK(set_distance(theirs, ours.positions) < 1e-12);
    }
  }
}

TEST_CASE("interpolating sqrt3 keeps old vertices, boundaries included") {
  const test::Mesh m = perturbed(test::grid(4, 3, true));
  const test::Refined r = test::refine_mesh(m, "interpolating-sqrt3", 4);
  // Every level's first vertices are the previous level's: compose back to the base.
  std::vector<double> p = m.positions;
  for (int l = 0; l < 4; ++l) {
    const std::vector<double> next = interpolate(r.hierarchy, l + 1, m.positions, 3);
    for (size_t i = 0; i < p.size(); ++i) CHECK(next[i] == doctest::Approx(p[i]).epsilon(1e-13));
    p = next;
  }
}

TEST_CASE("interpolating sqrt3 has linear precision on a planar regular lattice, boundaries included") {
  // On an affine image of the regular triangular lattice every face point is its face's
  // centroid: the regular stencil by symmetry, the boundary faces because a missing tip is
  // the reflection of a face vertex (1/2 c + 1/3 (a + b) - 1/12 (two tips) and
  // 7/24 ear + 3/8 (two others) - 1/24 tip both reduce to the centroid there), and the
  // trisection points of a straight, evenly spaced boundary sit at 1/3 and 2/3.
  test::Mesh m = test::grid(6, 5, true);
  for (size_t i = 0; i < m.positions.size(); i += 3) {
    const double x = m.positions[i], y = m.positions[i + 1];
    m.positions[i] = 2 * x + 0.5 * y + 1, m.positions[i + 1] = 0.3 * x + y, m.positions[i + 2] = 0.2 * x - 0.1 * y;
  }
  const test::Refined r = test::refine_mesh(m, "interpolating-sqrt3", 2);
  const Level& L0 = r.hierarchy.levels[0];
  const std::vector<double> p1 = interpolate(r.hierarchy, 1, m.positions, 3);
  for (Index f = 0; f < L0.face_count(); ++f)
    for (int d = 0; d < 3; ++d) {
      double centroid = 0;
      for (Index v : L0.face(f)) centroid += m.positions[3 * v + d] / 3;
      CHECK(p1[3 * (L0.vertex_count + f) + d] == doctest::Approx(centroid).epsilon(1e-13));
    }
  // Level 2 lies on the plane of the base (an affine image of z = 0).
  for (size_t i = 0; i < r.positions.size(); i += 3) {
    const double x = r.positions[i], y = r.positions[i + 1];
    // Invert x' = 2x + 0.5y + 1, y' = 0.3x + y, then z' = 0.2x - 0.1y.
    const double det = 2 - 0.15, u = ((x - 1) - 0.5 * y) / det, v = (2 * y - 0.3 * (x - 1)) / det;
    CHECK(r.positions[i + 2] == doctest::Approx(0.2 * u - 0.1 * v).epsilon(1e-12));
  }
}

TEST_CASE("interpolating sqrt3 boundary: cubic Lagrange trisection (-5/81, 20/27, 10/27, -4/81)") {
  const test::Mesh m = perturbed(test::grid(5, 4, true));
  const test::Refined r = test::refine_mesh(m, "interpolating-sqrt3", 2);
  const Level& L1 = r.hierarchy.levels[1];
  const ChildOrigins& o = r.hierarchy.origins[1];
  const StencilTable& t = r.hierarchy.stencils[1];
  int checked = 0;
  for (Index c = 0; c < Index(o.kind.size()); ++c) {
    if (o.kind[c] != OriginKind::Edge) continue;  // the trisection points of boundary edges
    const Index e = o.parent[c];
    const Index a = L1.edge_vertices[2 * e], b = L1.edge_vertices[2 * e + 1];
    const auto row = row_of(t, c);
    // Beside a boundary corner the curve's missing point is extrapolated (fewer points);
    // the planar test above covers those rows.
    if (row.size() != 4) continue;
    // Near end a or near end b: 20/27 on the near end, 10/27 on the far one.
    const bool near_a = std::abs(row.at(a) - 20.0 / 27) < 1e-12;
    CHECK(row.at(near_a ? a : b) == doctest::Approx(20.0 / 27));
    CHECK(row.at(near_a ? b : a) == doctest::Approx(10.0 / 27));
    double rest = 0;
    for (const auto& entry : row)
      if (entry.first != a && entry.first != b) rest += entry.second;
    CHECK(rest == doctest::Approx(-9.0 / 81));
    ++checked;
  }
  // Two per boundary edge of the level-1 mesh (5 + 4 + 5 + 4 edges), less the 8 beside a corner.
  CHECK(checked == 2 * 18 - 8);
}

TEST_CASE("subdiv validate accepts interpolating-sqrt3 and its boundary curve") {
  for (const char* name : {"interpolating-sqrt3", "ternary-lagrange"}) {
    const ValidationReport report = validate_scheme_file(name, 3, 16);
    CAPTURE(name);
    for (const auto& e : report.errors) CAPTURE(e.message);
    CHECK(report.errors.empty());
    CHECK(report.checks > 0);
  }
}
