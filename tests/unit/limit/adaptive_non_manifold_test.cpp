// Adaptive refinement of non-manifold meshes (limit/adaptive_refine.h): flaps on hinges of
// one to three edges, two sheets through one vertex, a face running its shared edge the wrong
// way; Catmull-Clark and Loop, both boundary modes. Checked against uniform refinement of the
// same mesh (engine/refiner.h, itself checked against OpenSubdiv's Far on non-manifold meshes
// in tests/unit/topology) and the base mesh's own topology:
// - with every face split (a tolerance of 1e-300) the output is the uniform level L: the same
//   points and the same faces over them;
// - feature-adaptive, every vertex is a point of a uniform level, no two vertices share a
//   position (a hinge's points are one vertex, not one per flap), every edge has as many faces
//   as the base edge it lies on (k on a hinge of k flaps, 1 on the boundary) or 2 inside a base
//   face (no crack, no T-junction), and the Euler characteristic is the uniform level's;
// - with `limit` every corner is the limit surface's point at its (base face, u, v), and
//   OpenSubdiv's Bfr's there;
// - the same with the transitions written as triangles and quads.
#include <doctest/doctest.h>

#include "unit/limit/bfr_surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/io/mesh_data.h"
#include "framework/limit/adaptive_refine.h"
#include "framework/limit/limit_surface.h"
#include "framework/pipeline/adaptive_request.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"
#include "unit/limit/non_manifold_meshes.h"

using namespace subdiv;
using namespace subdiv::non_manifold_test;

namespace {

struct Case {
  const char* name;
  test::Mesh mesh;
  const char* scheme;
  bool triangles;
};

std::vector<Case> cases() {
  return {{"three flaps on one hinge edge", book(3, 1), "catmull-clark", false},
          {"three flaps on a hinge of three edges", book(3, 3), "catmull-clark", false},
          {"four flaps on a hinge of two edges", book(4, 2), "catmull-clark", false},
          {"two sheets through one vertex", bow_tie(), "catmull-clark", false},
          {"a face running its shared edge the wrong way", flipped_face(), "catmull-clark", false},
          {"Loop: three flaps on a hinge of three edges", triangulated(book(3, 3)), "loop", true},
          {"Loop: two sheets through one vertex", triangulated(bow_tie()), "loop", true},
          {"Loop: a face running its shared edge the wrong way", triangulated(flipped_face()), "loop", true}};
}

constexpr BoundaryInterpolation kModes[] = {BoundaryInterpolation::EdgesAndCorners, BoundaryInterpolation::EdgesOnly};

Level level_of(const AdaptiveMesh& m) {
  return build_level(Index(m.positions.size() / 3), m.face_offsets, m.face_vertices);
}

size_t face_count(const AdaptiveMesh& m) { return m.face_offsets.size() - 1; }

int euler(const Level& L) { return int(L.vertex_count - L.edge_count() + L.face_count()); }

// Uniform refinement of the same mesh: every level's points.
struct Uniform {
  Hierarchy h;
  std::vector<std::vector<double>> points;  // per level 0..L
};

Uniform uniform(const Scheme& scheme, const Level& base, const std::vector<double>& positions, int levels,
                const FeatureOptions& features) {
  RefineOptions o;
  o.levels = levels;
  o.features = features;
  Uniform u{refine(scheme, base, o), {}};
  for (int l = 0; l <= levels; ++l) u.points.push_back(interpolate(u.h, l, positions, 3));
  return u;
}

double distance(const double* a, const double* b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// The vertex of `points` nearest to p, and how far it is.
std::pair<Index, double> nearest(const std::vector<double>& points, const double* p) {
  std::pair<Index, double> best{kNone, 1e300};
  for (size_t v = 0; v < points.size() / 3; ++v)
    if (const double d = distance(points.data() + 3 * v, p); d < best.second) best = {Index(v), d};
  return best;
}

// How far the vertex farthest from every uniform level's points is: a vertex is placed where
// the finest level that computed it puts it.
double farthest_from_uniform_points(const AdaptiveMesh& m, const Uniform& u) {
  double worst = 0;
  for (size_t v = 0; v < m.positions.size() / 3; ++v) {
    double d = 1e300;
    for (const auto& points : u.points) d = std::min(d, nearest(points, &m.positions[3 * v]).second);
    worst = std::max(worst, d);
  }
  return worst;
}

// The side of the base face's (u, v) domain both points lie on, or -1: quads (0,0) (1,0)
// (1,1) (0,1), triangles (0,0) (1,0) (0,1); side k runs from corner k to corner k + 1.
int common_side(std::array<double, 2> a, std::array<double, 2> b, bool triangles) {
  auto on = [&](int side, std::array<double, 2> p) {
    const double u = p[0], v = p[1];
    if (triangles) return side == 0 ? v == 0 : side == 1 ? u + v == 1 : u == 0;
    return side == 0 ? v == 0 : side == 1 ? u == 1 : side == 2 ? v == 1 : u == 0;
  };
  for (int side = 0; side < (triangles ? 3 : 4); ++side)
    if (on(side, a) && on(side, b)) return side;
  return -1;
}

// Every edge of the output has the faces the base topology gives it: an edge along base edge
// e has e's faces (k on a hinge of k flaps, 1 on the boundary), one inside a base face has 2.
// A crack (a hinge's vertices doubled) or a T-junction leaves edges with fewer faces. Returns
// the number of edges on hinges.
int check_edges(const AdaptiveMesh& m, const Level& base, bool triangles) {
  const Level L = level_of(m);
  int wrong = 0, hinge = 0;
  for (Index e = 0; e < L.edge_count(); ++e) {
    const Index f = L.faces_of_edge(e)[0];
    const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
    std::array<double, 2> ua{}, ub{};
    for (Index c = m.face_offsets[size_t(f)]; c < m.face_offsets[size_t(f) + 1]; ++c) {
      if (m.face_vertices[size_t(c)] == a) ua = m.corner_uv[size_t(c)];
      if (m.face_vertices[size_t(c)] == b) ub = m.corner_uv[size_t(c)];
    }
    const Index bf = m.base_face[size_t(f)];
    const int side = common_side(ua, ub, triangles);
    const Index expected = side < 0 ? 2 : base.edge_face_count(base.face_edge_list(bf)[side]);
    wrong += L.edge_face_count(e) != expected;
    hinge += expected > 2;
  }
  CHECK(wrong == 0);
  return hinge;
}

// No two vertices at one position: the flaps' copies of a hinge point are welded.
void check_no_duplicate_points(const AdaptiveMesh& m) {
  const size_t n = m.positions.size() / 3;
  int doubled = 0;
  for (size_t v = 0; v < n; ++v)
    for (size_t w = 0; w < v; ++w) doubled += distance(&m.positions[3 * v], &m.positions[3 * w]) < 1e-12;
  CHECK(doubled == 0);
}

void check_watertight(const AdaptiveMesh& m, const Level& base, bool triangles, const Uniform& u, int levels) {
  // Each hinge edge isolated to level L in every flap: 2^L segments, each with all the flaps.
  int hinges = 0;
  for (Index e = 0; e < base.edge_count(); ++e) hinges += base.edge_face_count(e) > 2;
  CHECK(check_edges(m, base, triangles) == hinges << levels);
  check_no_duplicate_points(m);
  CHECK(euler(level_of(m)) == euler(u.h.levels[size_t(levels)]));
}

AdaptiveOptions options(int levels, BoundaryInterpolation mode) {
  AdaptiveOptions o;
  o.levels = levels;
  o.features.boundary = mode;
  return o;
}

}  // namespace

TEST_CASE("adaptive refinement of non-manifold meshes splitting every face is the uniform level") {
  for (const Case& c : cases())
    for (BoundaryInterpolation mode : kModes)
      for (int levels : {1, 3}) {
        const std::string name = c.name;
        CAPTURE(name);
        CAPTURE(int(mode));
        CAPTURE(levels);
        const auto scheme = load_scheme(c.scheme);
        const Level base = c.mesh.level();
        REQUIRE_FALSE(base.manifold());
        LimitSurfaceOptions lo;
        lo.features.boundary = mode;
        const LimitSurface surface(scheme, base, lo);
        AdaptiveOptions o = options(levels, mode);
        o.tolerance = 1e-300;
        o.surface = &surface;
        const AdaptiveMesh m = refine_adaptive(*scheme, base, c.mesh.positions, o);
        const Uniform u = uniform(*scheme, base, c.mesh.positions, levels, o.features);
        const Level& U = u.h.levels[size_t(levels)];
        REQUIRE(Index(face_count(m)) == U.face_count());
        REQUIRE(Index(m.positions.size() / 3) == U.vertex_count);
        // Each vertex is a uniform vertex (so, with as many vertices and none doubled, each
        // uniform vertex once), and each face is a uniform face over those vertices.
        std::vector<Index> to_uniform;
        double worst = 0;
        for (size_t v = 0; v < m.positions.size() / 3; ++v) {
          const auto [w, d] = nearest(u.points[size_t(levels)], &m.positions[3 * v]);
          to_uniform.push_back(w);
          worst = std::max(worst, d);
        }
        CHECK(worst < 1e-12);
        std::map<std::vector<Index>, int> faces;
        for (Index f = 0; f < U.face_count(); ++f) {
          std::vector<Index> key(U.face(f).begin(), U.face(f).end());
          std::sort(key.begin(), key.end());
          ++faces[key];
        }
        for (size_t f = 0; f < face_count(m); ++f) {
          std::vector<Index> key;
          for (Index k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k)
            key.push_back(to_uniform[size_t(m.face_vertices[size_t(k)])]);
          std::sort(key.begin(), key.end());
          --faces[key];
        }
        int unmatched = 0;
        for (const auto& entry : faces) unmatched += entry.second != 0;
        CHECK(unmatched == 0);
        check_watertight(m, base, c.triangles, u, levels);
      }
}

TEST_CASE("feature-adaptive refinement of non-manifold meshes: watertight, a hinge's points shared, uniform points") {
  constexpr int kLevels = 3;
  for (const Case& c : cases())
    for (BoundaryInterpolation mode : kModes)
      for (AdaptiveTransitions transitions : {AdaptiveTransitions::Polygons, AdaptiveTransitions::Triangles}) {
        const std::string name = c.name;
        CAPTURE(name);
        CAPTURE(int(mode));
        CAPTURE(int(transitions));
        const auto scheme = load_scheme(c.scheme);
        const Level base = c.mesh.level();
        AdaptiveOptions o = options(kLevels, mode);
        o.transitions = transitions;
        const AdaptiveMesh m = refine_adaptive(*scheme, base, c.mesh.positions, o);
        const Uniform u = uniform(*scheme, base, c.mesh.positions, kLevels, o.features);
        check_watertight(m, base, c.triangles, u, kLevels);
        CHECK(face_count(m) < size_t(m.uniform_faces));
        CHECK(m.uniform_faces == u.h.levels[kLevels].face_count());
        CHECK(farthest_from_uniform_points(m, u) < 1e-12);
        if (transitions == AdaptiveTransitions::Triangles)
          for (size_t f = 0; f < face_count(m); ++f) {
            const Index n = m.face_offsets[f + 1] - m.face_offsets[f];
            CHECK((n == 3 || n == 4));
          }
        MESSAGE(name, ": ", face_count(m), " faces against ", m.uniform_faces, " uniform");
      }
}

TEST_CASE("adaptive refinement of non-manifold meshes with limit positions: the limit surface's points, Bfr's") {
  constexpr int kLevels = 3;
  for (const Case& c : cases())
    for (BoundaryInterpolation mode : kModes) {
      const std::string name = c.name;
      CAPTURE(name);
      CAPTURE(int(mode));
      const auto scheme = load_scheme(c.scheme);
      const Level base = c.mesh.level();
      LimitSurfaceOptions lo;
      lo.features.boundary = mode;
      const LimitSurface surface(scheme, base, lo);
      AdaptiveOptions o = options(kLevels, mode);
      o.limit = true;
      o.surface = &surface;
      const AdaptiveMesh m = refine_adaptive(*scheme, base, c.mesh.positions, o);
      const Uniform u = uniform(*scheme, base, c.mesh.positions, kLevels, o.features);
      check_watertight(m, base, c.triangles, u, kLevels);
#ifdef SUBDIV_HAVE_OPENSUBDIV
      subdiv_test::OsdOptions oo;
      oo.scheme = c.triangles ? subdiv_test::OsdScheme::Loop : subdiv_test::OsdScheme::CatmullClark;
      oo.boundary = mode == BoundaryInterpolation::EdgesOnly ? subdiv_test::OsdBoundary::EdgesOnly
                                                             : subdiv_test::OsdBoundary::EdgesAndCorners;
      const subdiv_test::BfrLimit bfr(subdiv_test::osd_mesh(c.mesh), oo, 10, 10);
#endif
      double ours = 0, theirs = 0;
      for (size_t f = 0; f < face_count(m); ++f)
        for (Index k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k) {
          const auto uv = m.corner_uv[size_t(k)];
          const double* p = &m.positions[size_t(3 * m.face_vertices[size_t(k)])];
          const LimitSample s = surface.evaluate(m.base_face[f], uv[0], uv[1], c.mesh.positions, 3, 0);
          ours = std::max(ours, distance(p, s.position.data()));
#ifdef SUBDIV_HAVE_OPENSUBDIV
          theirs = std::max(theirs, distance(p, bfr.evaluate(int(m.base_face[f]), uv[0], uv[1]).p.data()));
#endif
        }
      CHECK(ours < 1e-12);
      CHECK(theirs < 1e-12);
    }
}

TEST_CASE("adaptive refinement of non-manifold meshes: a semi-sharp edge at a hinge follows uniform refinement") {
  // The limit evaluation refuses it (its rule changes as the sharpness decays, which the cut
  // into sheets does not follow); the levels themselves are uniform refinement's.
  constexpr int kLevels = 3;
  const test::Mesh mesh = book(3, 2);
  Level base = mesh.level();
  base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
  base.edge_sharpness[size_t(find_edge(base, 1, 4))] = 1.5f;  // from the hinge's middle vertex outwards
  const auto scheme = load_scheme("catmull-clark");
  for (BoundaryInterpolation mode : kModes)
    for (CreaseMethod method : {CreaseMethod::Uniform, CreaseMethod::Chaikin}) {
      CAPTURE(int(mode));
      CAPTURE(int(method));
      AdaptiveOptions o = options(kLevels, mode);
      o.features.crease_method = method;
      const AdaptiveMesh m = refine_adaptive(*scheme, base, mesh.positions, o);
      const Uniform u = uniform(*scheme, base, mesh.positions, kLevels, o.features);
      check_watertight(m, base, false, u, kLevels);
      CHECK(farthest_from_uniform_points(m, u) < 1e-12);
    }
  LimitSurfaceOptions lo;
  CHECK_THROWS_WITH_AS(LimitSurface(scheme, base, lo), doctest::Contains("semi-sharp edge ends at this non-manifold"),
                       Error);
}

TEST_CASE("adaptive refinement of non-manifold meshes refuses a face that repeats a vertex") {
  test::Mesh mesh = book(3, 1);
  mesh.add_face({2, 3, 4, 4});
  const AdaptiveOptions o = options(2, BoundaryInterpolation::EdgesAndCorners);
  CHECK_THROWS_WITH_AS(refine_adaptive(*load_scheme("catmull-clark"), mesh.level(), mesh.positions, o),
                       doctest::Contains("face 6 repeats vertex 4"), Error);
}

TEST_CASE("adaptive refinement of non-manifold meshes carries face-varying channels") {
  // A seamless channel that is an affine image of the positions, in the mode `none` (refined
  // like the positions): each corner's value is that image of its vertex, with and without
  // limit positions. With the boundary mode edges-only: in the mode `none` a value mesh's
  // boundary corner is not sharp, as OpenSubdiv's face-varying channels take it, where the
  // mode edges-and-corners makes the vertex's sharp.
  MeshData d = test::mesh_data(book(3, 2));
  FaceVaryingArray a{"st", 2, {}, {d.face_vertices.begin(), d.face_vertices.end()}, ArrayRole::Data};
  const auto image = [](const double* p) { return std::array<double, 2>{p[0] + 2 * p[2], p[1] - p[2] + 0.5}; };
  for (size_t v = 0; v < d.positions.size() / 3; ++v) {
    const auto st = image(&d.positions[3 * v]);
    a.values.insert(a.values.end(), st.begin(), st.end());
  }
  d.face_varying.push_back(std::move(a));
  for (bool limit : {false, true}) {
    CAPTURE(limit);
    AdaptiveRequest r;
    r.refine.mesh = d;
    r.refine.mesh_name = "flaps";
    r.refine.scheme.text = "catmull-clark";
    r.refine.shape.face_varying = FaceVaryingLinear::None;
    r.refine.shape.boundary = BoundaryInterpolation::EdgesOnly;
    r.refine.levels = 3;
    r.limit = limit;
    const AdaptiveResult out = refine_adaptive_request(std::move(r));
    REQUIRE(out.face_varying.size() == 1);
    const FaceVaryingArray& st = out.face_varying.front();
    REQUIRE(st.indices.size() == out.mesh.face_vertices.size());
    double worst = 0;
    for (size_t c = 0; c < st.indices.size(); ++c) {
      const auto expected = image(&out.mesh.positions[size_t(3 * out.mesh.face_vertices[c])]);
      for (size_t k = 0; k < 2; ++k)
        worst = std::max(worst, std::abs(st.values[2 * size_t(st.indices[c]) + k] - expected[k]));
    }
    CHECK(worst < 1e-13);
  }
}
