// The OpenSubdiv reference helper checked on its own: OpenSubdiv's level-1 points against
// the papers' formulas computed here by hand, the origin bookkeeping, and point matching.
#include <doctest/doctest.h>

#include "support/osd_reference.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

#include <array>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

namespace {

using subdiv_test::OsdOrigin;
using Vec = std::array<double, 3>;

Vec add(Vec a, Vec b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec scale(Vec a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dist(Vec a, std::span<const double> b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

subdiv_test::OsdMesh cube() {
  subdiv_test::OsdMesh m;
  m.vertex_count = 8;
  m.xyz = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
  // Counter-clockwise seen from outside.
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  for (const auto& f : faces) {
    m.face_vertices.insert(m.face_vertices.end(), f, f + 4);
    m.face_offsets.push_back(int(m.face_vertices.size()));
  }
  return m;
}

subdiv_test::OsdMesh octahedron() {
  subdiv_test::OsdMesh m;
  m.vertex_count = 6;
  m.xyz = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  const int faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const auto& f : faces) {
    m.face_vertices.insert(m.face_vertices.end(), f, f + 3);
    m.face_offsets.push_back(int(m.face_vertices.size()));
  }
  return m;
}

// Brute-force adjacency of a small closed or open mesh, independent of both libraries.
struct Adjacency {
  std::vector<std::vector<int>> faces;
  std::set<std::pair<int, int>> edges;  // (min, max)
  Adjacency(const subdiv_test::OsdMesh& m) {
    for (size_t f = 0; f + 1 < m.face_offsets.size(); ++f) {
      faces.emplace_back(m.face_vertices.begin() + m.face_offsets[f], m.face_vertices.begin() + m.face_offsets[f + 1]);
      const auto& fv = faces.back();
      for (size_t i = 0; i < fv.size(); ++i) {
        const int a = fv[i], b = fv[(i + 1) % fv.size()];
        edges.insert({std::min(a, b), std::max(a, b)});
      }
    }
  }
  bool has(const std::vector<int>& f, int v) const { return std::find(f.begin(), f.end(), v) != f.end(); }
  bool face_has_edge(const std::vector<int>& f, int a, int b) const {
    for (size_t i = 0; i < f.size(); ++i) {
      const int x = f[i], y = f[(i + 1) % f.size()];
      if ((x == a && y == b) || (x == b && y == a)) return true;
    }
    return false;
  }
};

Vec point(const subdiv_test::OsdMesh& m, int v) { return {m.xyz[3 * v], m.xyz[3 * v + 1], m.xyz[3 * v + 2]}; }

Vec centroid(const subdiv_test::OsdMesh& m, const std::vector<int>& f) {
  Vec c{0, 0, 0};
  for (int v : f) c = add(c, point(m, v));
  return scale(c, 1.0 / double(f.size()));
}

}  // namespace

TEST_CASE("osd_reference: Catmull-Clark cube level 1 follows Catmull & Clark's formulas") {
  const auto mesh = cube();
  const auto osd = subdiv_test::osd_refine(mesh, {subdiv_test::OsdScheme::CatmullClark}, 1);
  REQUIRE(osd.levels.size() == 2);
  const auto& l1 = osd.levels[1];
  CHECK(l1.vertex_count == 26);
  CHECK(l1.face_count() == 24);
  CHECK(l1.edge_count() == 48);

  const Adjacency adj(mesh);
  const auto& l0 = osd.levels[0];
  int kinds[3] = {0, 0, 0};
  for (int c = 0; c < l1.vertex_count; ++c) {
    const int p = l1.origin_parent[c];
    Vec expected{};
    switch (l1.origin_kind[c]) {
      case OsdOrigin::Face: {
        ++kinds[2];
        expected = centroid(mesh, adj.faces[p]);
        break;
      }
      case OsdOrigin::Edge: {
        ++kinds[1];
        const int a = l0.edge_vertices[2 * p], b = l0.edge_vertices[2 * p + 1];
        // Edge point: average of the end points and the two adjacent face points.
        Vec sum = add(point(mesh, a), point(mesh, b));
        int faces = 0;
        for (const auto& f : adj.faces)
          if (adj.face_has_edge(f, a, b)) sum = add(sum, centroid(mesh, f)), ++faces;
        REQUIRE(faces == 2);
        expected = scale(sum, 0.25);
        break;
      }
      case OsdOrigin::Vertex: {
        ++kinds[0];
        // Vertex point: (n-3)/n v + 2R/n + Q/n, R the average of the edge midpoints,
        // Q the average of the face points around v.
        const Vec v = point(mesh, p);
        Vec r{0, 0, 0}, q{0, 0, 0};
        int n = 0, k = 0;
        for (const auto& [a, b] : adj.edges)
          if (a == p || b == p) r = add(r, scale(add(point(mesh, a), point(mesh, b)), 0.5)), ++n;
        for (const auto& f : adj.faces)
          if (adj.has(f, p)) q = add(q, centroid(mesh, f)), ++k;
        REQUIRE(n == 3);
        REQUIRE(k == 3);
        r = scale(r, 1.0 / n);
        q = scale(q, 1.0 / k);
        expected = add(add(scale(v, (n - 3.0) / n), scale(r, 2.0 / n)), scale(q, 1.0 / n));
        break;
      }
    }
    CHECK(dist(expected, l1.position(c)) < 1e-14);
  }
  CHECK(kinds[0] == 8);
  CHECK(kinds[1] == 12);
  CHECK(kinds[2] == 6);

  // The corner (1, 1, 1): R = (2/3, 2/3, 2/3), Q = (1/3, 1/3, 1/3), so 2R/3 + Q/3 = 5/9.
  CHECK(dist({5.0 / 9, 5.0 / 9, 5.0 / 9}, l1.position(6)) < 1e-15);
}

TEST_CASE("osd_reference: Loop octahedron level 1 follows Loop's formulas") {
  const auto mesh = octahedron();
  const auto osd = subdiv_test::osd_refine(mesh, {subdiv_test::OsdScheme::Loop}, 1);
  const auto& l1 = osd.levels[1];
  CHECK(l1.vertex_count == 6 + 12);
  CHECK(l1.face_count() == 32);
  const Adjacency adj(mesh);
  const auto& l0 = osd.levels[0];
  for (int c = 0; c < l1.vertex_count; ++c) {
    const int p = l1.origin_parent[c];
    Vec expected{};
    if (l1.origin_kind[c] == OsdOrigin::Edge) {
      // 3/8 on the end points, 1/8 on the two opposite vertices.
      const int a = l0.edge_vertices[2 * p], b = l0.edge_vertices[2 * p + 1];
      expected = scale(add(point(mesh, a), point(mesh, b)), 3.0 / 8);
      for (const auto& f : adj.faces)
        if (adj.face_has_edge(f, a, b))
          for (int v : f)
            if (v != a && v != b) expected = add(expected, scale(point(mesh, v), 1.0 / 8));
    } else {
      REQUIRE(l1.origin_kind[c] == OsdOrigin::Vertex);
      // (1 - n beta) v + beta * sum of neighbours, beta = (5/8 - (3/8 + cos(2 pi/n)/4)^2) / n.
      std::vector<int> ring;
      for (const auto& [a, b] : adj.edges)
        if (a == p || b == p) ring.push_back(a == p ? b : a);
      const double n = double(ring.size());
      const double t = 3.0 / 8 + std::cos(2 * std::numbers::pi / n) / 4;
      const double beta = (5.0 / 8 - t * t) / n;
      expected = scale(point(mesh, p), 1 - n * beta);
      for (int v : ring) expected = add(expected, scale(point(mesh, v), beta));
    }
    CHECK(dist(expected, l1.position(c)) < 1e-14);
  }
}

TEST_CASE("osd_reference: boundary modes, creases and corners on an open quad grid") {
  // A 2 x 2 grid of quads in the plane z = 0, vertices (i, j) at index 3j + i.
  subdiv_test::OsdMesh grid;
  grid.vertex_count = 9;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) grid.xyz.insert(grid.xyz.end(), {double(i), double(j), 0.0});
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int v = 3 * j + i;
      grid.face_vertices.insert(grid.face_vertices.end(), {v, v + 1, v + 4, v + 3});
      grid.face_offsets.push_back(int(grid.face_vertices.size()));
    }
  // Lift the centre so the rules have something to move.
  grid.xyz[3 * 4 + 2] = 1.0;

  SUBCASE("edges and corners: the valence-2 corner stays") {
    const auto osd = subdiv_test::osd_refine(grid, {subdiv_test::OsdScheme::CatmullClark}, 1);
    CHECK(dist({0, 0, 0}, osd.levels[1].position(0)) == 0.0);
    // Boundary edge (0,0)-(1,0) gets its midpoint.
    const auto& l0 = osd.levels[0];
    const auto& l1 = osd.levels[1];
    for (int c = 0; c < l1.vertex_count; ++c)
      if (l1.origin_kind[c] == OsdOrigin::Edge) {
        const int a = l0.edge_vertices[2 * l1.origin_parent[c]], b = l0.edge_vertices[2 * l1.origin_parent[c] + 1];
        if (std::min(a, b) == 0 && std::max(a, b) == 1) CHECK(dist({0.5, 0, 0}, l1.position(c)) < 1e-15);
      }
    // Boundary vertex (1, 0) of valence 3: cubic B-spline 1/8, 3/4, 1/8 along the boundary.
    CHECK(dist({1, 0, 0}, l1.position(1)) < 1e-15);
  }
  SUBCASE("edges only: the corner follows the curve rule") {
    const auto osd = subdiv_test::osd_refine(
        grid, {subdiv_test::OsdScheme::CatmullClark, subdiv_test::OsdBoundary::EdgesOnly}, 1);
    // 1/8 (1,0,0) + 3/4 (0,0,0) + 1/8 (0,1,0).
    CHECK(dist({1.0 / 8, 1.0 / 8, 0}, osd.levels[1].position(0)) < 1e-15);
  }
  SUBCASE("an infinitely sharp interior crease through the centre") {
    auto creased = grid;
    creased.creases = {{1, 4, 10.f}, {4, 7, 10.f}};
    const auto osd = subdiv_test::osd_refine(creased, {subdiv_test::OsdScheme::CatmullClark}, 1);
    // The centre is a crease vertex: 1/8 (1,0,0) + 3/4 (1,1,1) + 1/8 (1,2,0).
    CHECK(dist({1, 1, 0.75}, osd.levels[1].position(4)) < 1e-15);
  }
  SUBCASE("a tagged corner stays") {
    auto cornered = grid;
    cornered.corners = {{4, 10.f}};
    const auto osd = subdiv_test::osd_refine(cornered, {subdiv_test::OsdScheme::CatmullClark}, 1);
    CHECK(dist({1, 1, 1}, osd.levels[1].position(4)) == 0.0);
  }
  SUBCASE("bilinear: face points are centroids, vertices stay") {
    const auto osd = subdiv_test::osd_refine(grid, {subdiv_test::OsdScheme::Bilinear}, 1);
    const auto& l1 = osd.levels[1];
    CHECK(l1.vertex_count == 9 + 4 + 12);
    for (int v = 0; v < 9; ++v) CHECK(dist(point(grid, v), l1.position(v)) == 0.0);
    CHECK(dist({0.5, 0.5, 0.25}, l1.position(9)) < 1e-15);  // first face child: face 0
  }
}

TEST_CASE("osd_reference: origins chain across levels") {
  const auto osd = subdiv_test::osd_refine(cube(), {subdiv_test::OsdScheme::CatmullClark}, 3);
  REQUIRE(osd.levels.size() == 4);
  int v = 26 + 48 + 24, f = 6 * 4 * 4 * 4;
  CHECK(osd.levels[2].vertex_count == v);
  CHECK(osd.levels[3].face_count() == f);
  // V - E + F = 2 at every level.
  for (const auto& l : osd.levels) CHECK(l.vertex_count - l.edge_count() + l.face_count() == 2);
}

// A stand-in for a SubdivKit hierarchy, made from OpenSubdiv's own levels but numbered the
// SubdivKit way (children of vertices, then edges, then faces) and with every edge and
// face list reversed, so that no index agrees with OpenSubdiv's by accident. `ours_to_osd`
// receives, per level, the vertex map the helper has to rediscover.
subdiv::Hierarchy renumbered(const subdiv_test::OsdRefinement& osd, std::vector<std::vector<int>>& ours_to_osd) {
  subdiv::Hierarchy h;
  const int levels = int(osd.levels.size());
  std::vector<int> osd_to_ours(size_t(osd.levels[0].vertex_count));
  std::iota(osd_to_ours.begin(), osd_to_ours.end(), 0);
  ours_to_osd.assign(1, osd_to_ours);
  std::vector<int> osd_face_to_ours, osd_edge_to_ours;
  for (int l = 0; l < levels; ++l) {
    const auto& ol = osd.levels[size_t(l)];
    subdiv::Level level;
    level.vertex_count = ol.vertex_count;
    const int F = ol.face_count(), E = ol.edge_count();
    osd_face_to_ours.assign(size_t(F), 0);
    osd_edge_to_ours.assign(size_t(E), 0);
    for (int of = F - 1; of >= 0; --of) {  // our face F-1-of is OpenSubdiv's face of
      osd_face_to_ours[size_t(of)] = F - 1 - of;
      for (int i = ol.face_offsets[of]; i < ol.face_offsets[of + 1]; ++i)
        level.face_vertices.push_back(osd_to_ours[size_t(ol.face_vertices[i])]);
      level.face_offsets.push_back(subdiv::Index(level.face_vertices.size()));
    }
    for (int oe = E - 1; oe >= 0; --oe) {
      osd_edge_to_ours[size_t(oe)] = E - 1 - oe;
      level.edge_vertices.push_back(osd_to_ours[size_t(ol.edge_vertices[2 * oe + 1])]);
      level.edge_vertices.push_back(osd_to_ours[size_t(ol.edge_vertices[2 * oe])]);
    }
    h.levels.push_back(std::move(level));
    if (l + 1 == levels) break;

    // Number the next level's vertices: vertex children, edge children, face children.
    const auto& next = osd.levels[size_t(l) + 1];
    const int V = ol.vertex_count;
    subdiv::ChildOrigins origins;
    origins.kind.resize(size_t(next.vertex_count));
    origins.parent.resize(size_t(next.vertex_count));
    std::vector<int> next_osd_to_ours(size_t(next.vertex_count));
    for (int c = 0; c < next.vertex_count; ++c) {
      const int p = next.origin_parent[size_t(c)];
      int ours = 0;
      switch (next.origin_kind[size_t(c)]) {
        case OsdOrigin::Vertex: ours = osd_to_ours[size_t(p)]; break;
        case OsdOrigin::Edge: ours = V + osd_edge_to_ours[size_t(p)]; break;
        case OsdOrigin::Face: ours = V + E + osd_face_to_ours[size_t(p)]; break;
      }
      next_osd_to_ours[size_t(c)] = ours;
      origins.kind[size_t(ours)] = next.origin_kind[size_t(c)] == OsdOrigin::Vertex ? subdiv::OriginKind::Vertex
                                   : next.origin_kind[size_t(c)] == OsdOrigin::Edge ? subdiv::OriginKind::Edge
                                                                                     : subdiv::OriginKind::Face;
      origins.parent[size_t(ours)] = next.origin_kind[size_t(c)] == OsdOrigin::Vertex ? osd_to_ours[size_t(p)]
                                     : next.origin_kind[size_t(c)] == OsdOrigin::Edge ? osd_edge_to_ours[size_t(p)]
                                                                                       : osd_face_to_ours[size_t(p)];
    }
    h.origins.push_back(std::move(origins));
    osd_to_ours = std::move(next_osd_to_ours);
    std::vector<int> inverse(osd_to_ours.size());
    for (size_t c = 0; c < osd_to_ours.size(); ++c) inverse[size_t(osd_to_ours[c])] = int(c);
    ours_to_osd.push_back(std::move(inverse));
  }
  return h;
}

TEST_CASE("osd_reference: our_to_osd_vertices finds vertices through their origins") {
  for (const auto scheme : {subdiv_test::OsdScheme::CatmullClark, subdiv_test::OsdScheme::Loop}) {
    const bool loop = scheme == subdiv_test::OsdScheme::Loop;
    CAPTURE(loop);
    const auto osd = subdiv_test::osd_refine(loop ? octahedron() : cube(), {scheme}, 3);
    std::vector<std::vector<int>> expected;
    const subdiv::Hierarchy ours = renumbered(osd, expected);
    for (int l = 0; l <= 3; ++l) {
      CAPTURE(l);
      CHECK(subdiv_test::our_to_osd_vertices(osd, ours, l) == expected[size_t(l)]);
      const auto xyz = subdiv_test::osd_in_our_order(osd, ours, l);
      REQUIRE(xyz.size() == 3 * expected[size_t(l)].size());
      for (size_t v = 0; v < expected[size_t(l)].size(); ++v)
        CHECK(dist({xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]}, osd.levels[size_t(l)].position(expected[size_t(l)][v])) == 0.0);
    }
  }
}

TEST_CASE("osd_reference: a topology mismatch is reported, not guessed") {
  const auto osd = subdiv_test::osd_refine(cube(), {subdiv_test::OsdScheme::CatmullClark}, 1);
  std::vector<std::vector<int>> expected;
  subdiv::Hierarchy ours = renumbered(osd, expected);
  // Point one of our edge children at a pair of vertices that is not an edge.
  ours.levels[0].edge_vertices[0] = 0;
  ours.levels[0].edge_vertices[1] = 6;
  CHECK_THROWS_AS(subdiv_test::our_to_osd_vertices(osd, ours, 1), std::runtime_error);
}

TEST_CASE("osd_reference: match_points pairs permuted points and rejects moved ones") {
  const std::vector<double> a = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const std::vector<double> b = {1, 1, 0, 0, 1, 0, 0, 0, 1e-12, 1, 0, 0};
  const auto m = subdiv_test::match_points(a, b, 1e-9);
  CHECK(m.ok);
  CHECK(m.a_to_b == std::vector<int>{2, 3, 1, 0});
  CHECK(m.max_difference == doctest::Approx(1e-12));
  auto moved = b;
  moved[0] += 1e-6;
  CHECK_FALSE(subdiv_test::match_points(a, moved, 1e-9).ok);
  CHECK(subdiv_test::max_abs_difference(a, a) == 0.0);
  CHECK(std::isinf(subdiv_test::max_abs_difference(a, {a.data(), 3})));
}

#else

TEST_CASE("osd_reference: skipped, built without OpenSubdiv") {}

#endif
