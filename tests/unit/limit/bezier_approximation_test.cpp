// Loop & Schaefer's (2008) bicubic patches against properties of the construction and the
// exact limit: the B-spline patch reproduced where every valence is 4, C0 geometry, a
// normal field continuous across every edge (which the geometry patches' own is not at
// extraordinary vertices), the tangent masks' tangent plane the exact limit's, and the
// distance to the exact limit zero on regular faces, positive next to extraordinary
// vertices and shrinking as the control mesh is refined.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <random>

#include "framework/engine/refiner.h"
#include "framework/limit/bezier_approximation.h"
#include "framework/pipeline/approximation_request.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/cli_runner.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

PreparedEvaluation prepared(const test::Mesh& m, const std::string& scheme = "catmull-clark",
                              std::vector<CreaseTag> creases = {}) {
  EvaluateRequest r;
  r.mesh = test::mesh_data(m);
  r.mesh.creases = std::move(creases);
  r.scheme.text = scheme;
  return prepare_evaluation(std::move(r));
}

using limit_test::angle;
using limit_test::bumpy;
using limit_test::creases_along;
using limit_test::normal;
using limit_test::quad_split;

// Closed quad meshes with vertices of valence 3 to 6: the bipyramids' triangles split
// (apexes of valence n, the triangles' centres 3).
test::Mesh valences_3_to_5() { return quad_split(test::bipyramid(5)); }
test::Mesh valences_3_to_6() { return quad_split(test::bipyramid(6)); }

struct EdgeSides {
  double largest_position = 0, largest_tangent_angle = 0, largest_geometry_angle = 0;
  bool control_points_differ = false;
};

// The geometry control points along face corner k's edge, from corner k.
std::array<Point3, 4> boundary(const BezierPatch& p, int k) {
  std::array<Point3, 4> out;
  for (int s = 0; s < 4; ++s) {
    const int i = k == 0 ? s : k == 1 ? 3 : k == 2 ? 3 - s : 0;
    const int j = k == 0 ? 0 : k == 1 ? s : k == 2 ? 3 : 3 - s;
    out[size_t(s)] = p.geometry[size_t(j * 4 + i)];
  }
  return out;
}

bool same_boundary(const std::vector<BezierPatch>& patches, std::pair<Index, int> a, std::pair<Index, int> b) {
  const auto x = boundary(patches[size_t(a.first)], a.second), y = boundary(patches[size_t(b.first)], b.second);
  for (size_t s = 0; s < 4; ++s)
    if (x[s] != y[3 - s]) return false;
  return true;
}

// Along every interior edge, both faces' patches at the same points.
EdgeSides compare_edges(const Level& level, const std::vector<BezierPatch>& patches) {
  const auto directed = limit_test::directed_quad_edges(level);
  EdgeSides out;
  for (const auto& [e, fk] : directed) {
    if (!directed.contains({e.second, e.first})) continue;  // a boundary edge: one side only
    const auto& [g, l] = directed.at({e.second, e.first});
    for (double t : {0.0, 0.1, 0.37, 0.5, 0.81, 1.0}) {
      const auto a = limit_test::quad_edge_point(fk.second, t), b = limit_test::quad_edge_point(l, 1 - t);
      const PatchSample p = evaluate_patch(patches[size_t(fk.first)], a[0], a[1]);
      const PatchSample q = evaluate_patch(patches[size_t(g)], b[0], b[1]);
      for (int c = 0; c < 3; ++c)
        out.largest_position = std::max(out.largest_position, std::abs(p.position[size_t(c)] - q.position[size_t(c)]));
      // The boundary curves' control points themselves are the same numbers from both sides.
      if (t == 0.5) out.control_points_differ = out.control_points_differ || !same_boundary(patches, fk, {g, l});
      // Across an infinitely sharp crease the normal may jump: positions only.
      if (level.edge_sharp(level.face_edges[size_t(4 * fk.first + fk.second)]) > 0) continue;
      out.largest_tangent_angle = std::max(out.largest_tangent_angle, angle(normal(p.du, p.dv), normal(q.du, q.dv)));
      if (t > 0 && t < 1)  // the geometry patches' normals, away from the corners
        out.largest_geometry_angle = std::max(
            out.largest_geometry_angle, angle(normal(p.geometry_du, p.geometry_dv), normal(q.geometry_du, q.geometry_dv)));
    }
  }
  return out;
}

// At the points (faces[i], uv[2i], uv[2i + 1]): the largest distance of the patches from the
// exact limit, and of the tangent patches from the exact derivatives.
std::pair<double, double> against_exact(const PreparedEvaluation& p, const BezierApproximation& patches_set,
                                        const std::vector<Index>& faces, const std::vector<double>& uv) {
  const std::vector<BezierPatch>& patches = patches_set.patches;
  const ApproximatedPoints a = approximate_points(p, patches_set, faces, uv);
  const EvaluatedPoints exact = evaluate_limit_points(p, faces, uv, 1);
  double worst = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    const PatchSample s = evaluate_patch(patches[size_t(faces[i])], uv[2 * i], uv[2 * i + 1]);
    for (size_t c = 0; c < 3; ++c)
      worst = std::max({worst, std::abs(s.du[c] - exact.du[3 * i + c]), std::abs(s.dv[c] - exact.dv[3 * i + c])});
  }
  return {a.distances.largest, worst};
}

}  // namespace

TEST_CASE("where every valence is 4 the patches are the exact limit (the bicubic B-spline)") {
  const PreparedEvaluation p = prepared(test::torus(6, 5));
  const BezierApproximation patches_set = approximation_patches(p);
  const std::vector<BezierPatch>& patches = patches_set.patches;
  const auto [faces, uv] = limit_test::random_face_points(200, 30, 7);
  const auto [distance, derivatives] = against_exact(p, patches_set, faces, uv);
  CHECK(distance < 1e-12);
  CHECK(derivatives < 1e-11);  // the tangent patches are then the patch's own derivatives: the exact ones
}

TEST_CASE("patches meet with C0, and the tangent patches' normals are continuous where the geometry's are not") {
  for (const test::Mesh& m : {test::cube(), valences_3_to_5(), valences_3_to_6()}) {
    const PreparedEvaluation p = prepared(m);
    const BezierApproximation patches_set = approximation_patches(p);
  const std::vector<BezierPatch>& patches = patches_set.patches;
    const EdgeSides e = compare_edges(p.surface->base(), patches);
    CHECK_FALSE(e.control_points_differ);  // the shared boundary curve, computed alike from both sides
    CHECK(e.largest_position < 1e-14);     // evaluated from both sides: round-off only
    CHECK(e.largest_tangent_angle < 1e-12);
    CHECK(e.largest_geometry_angle > 1e-3);
  }
}

TEST_CASE("the tangent patches' normal at an extraordinary vertex is the exact limit normal") {
  for (const test::Mesh& m : {test::cube(), valences_3_to_5(), valences_3_to_6()}) {
    const PreparedEvaluation p = prepared(m);
    const BezierApproximation patches_set = approximation_patches(p);
  const std::vector<BezierPatch>& patches = patches_set.patches;
    const Level& base = p.surface->base();
    double worst = 0;
    for (Index f = 0; f < base.face_count(); ++f) {
      // The exact normal approaches the vertex's as h -> 0 (linearly: the limit is C1 there).
      const std::vector<Index> faces{f};
      const std::vector<double> uv{1e-60, 1e-60};
      const EvaluatedPoints exact = evaluate_limit_points(p, faces, uv, 1);
      const PatchSample s = evaluate_patch(patches[size_t(f)], 0, 0);
      const Point3 du{exact.du[0], exact.du[1], exact.du[2]}, dv{exact.dv[0], exact.dv[1], exact.dv[2]};
      worst = std::max(worst, angle(normal(s.du, s.dv), normal(du, dv)));
    }
    MESSAGE("largest angle to the exact normal at a corner: ", worst);
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("the distance to the exact limit: 0 on regular faces, positive next to extraordinary vertices, and "
          "smaller after one Catmull-Clark step") {
  // Split twice: faces away from the extraordinary vertices are regular.
  const test::Mesh m = quad_split(valences_3_to_6());
  const PreparedEvaluation p = prepared(m);
  const BezierApproximation patches_set = approximation_patches(p);
  const std::vector<BezierPatch>& patches = patches_set.patches;
  ApproximationDistances d;
  (void)approximated_limit_mesh(p, patches_set, 6, d);
  const Level& base = p.surface->base();
  int regular = 0, irregular = 0;
  for (Index f = 0; f < base.face_count(); ++f) {
    bool all4 = true;
    for (int k = 0; k < 4; ++k) {
      const Index v = base.face_vertices[size_t(4 * f + k)];
      all4 = all4 && base.vertex_ring_offsets[size_t(v) + 1] - base.vertex_ring_offsets[size_t(v)] == 4;
    }
    if (all4) {
      ++regular;
      CHECK(d.per_face[size_t(f)] < 1e-12);
    } else {
      ++irregular;
      CHECK(d.per_face[size_t(f)] > 1e-6);
    }
  }
  CHECK(regular > 0);
  CHECK(irregular > 0);
  // One Catmull-Clark step: the same limit surface, its extraordinary vertices now ringed by
  // smaller faces.
  const auto scheme = load_scheme("catmull-clark");
  RefineOptions options;
  options.levels = 1;
  const Hierarchy h = refine(*scheme, m.level(), options);
  test::Mesh finer;
  finer.vertex_count = h.levels[1].vertex_count;
  finer.positions = apply_step(h, 0, m.positions, 3);
  finer.offsets.assign(h.levels[1].face_offsets.begin(), h.levels[1].face_offsets.end());
  finer.corners.assign(h.levels[1].face_vertices.begin(), h.levels[1].face_vertices.end());
  const PreparedEvaluation q = prepared(finer);
  ApproximationDistances e;
  (void)approximated_limit_mesh(q, approximation_patches(q), 6, e);
  MESSAGE("largest distance ", d.largest, " -> ", e.largest, ", mean ", d.mean, " -> ", e.mean);
  CHECK(e.largest < d.largest);
  CHECK(e.mean < 0.5 * d.mean);
}

TEST_CASE("schemes whose regular patch is not the bicubic B-spline are refused with the reason") {
  const test::Mesh torus = test::torus(6, 5);
  CHECK(bezier_approximation_unsupported(load_scheme("catmull-clark")).empty());
  CHECK(bezier_approximation_unsupported(load_scheme("doo-sabin")).find("not the bicubic B-spline") !=
        std::string::npos);
  CHECK(bezier_approximation_unsupported(load_scheme("bilinear")).find("not the bicubic B-spline") != std::string::npos);
  CHECK(bezier_approximation_unsupported(load_scheme("loop")).find("triangles") != std::string::npos);
  (void)torus;
}

namespace {


// The largest distance to the exact limit and of the tangent patches from the exact
// derivatives, at random points of every face.
std::pair<double, double> worst_against_exact(const PreparedEvaluation& p, const BezierApproximation& patches_set) {
  const std::vector<BezierPatch>& patches = patches_set.patches;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Index> faces;
  std::vector<double> uv;
  for (Index f = 0; f < Index(patches.size()); ++f)
    for (int i = 0; i < 8; ++i) {
      faces.push_back(f);
      uv.push_back(unit(rng));
      uv.push_back(unit(rng));
    }
  return against_exact(p, patches_set, faces, uv);
}

}  // namespace

TEST_CASE("boundaries, infinitely sharp creases and corners: the exact limit where every sector is regular") {
  // An open grid: corners of one face (kept), boundary vertices with two faces, valence 4 inside.
  const test::Mesh grid = bumpy(test::grid(6, 5));
  // A torus with two crease loops (rings v = 0 and v = 3 of 6): two faces on each side.
  const test::Mesh torus = test::torus(8, 6);
  const auto loops = creases_along(torus, [](Index a, Index b) { return a / 8 == b / 8 && (a / 8 == 0 || a / 8 == 3); });
  // The cube with all 12 edges infinitely sharp: three crease edges at each corner, one face
  // between them; the limit is the cube itself.
  const test::Mesh cube = test::cube();
  const auto edges = creases_along(cube, [](Index, Index) { return true; });
  for (const auto& [mesh, creases] : {std::pair{grid, std::vector<CreaseTag>{}}, std::pair{torus, loops},
                                      std::pair{cube, edges}}) {
    const Index vertices = mesh.vertex_count;  // clang 14: no structured binding in CAPTURE
    const PreparedEvaluation p = prepared(mesh, "catmull-clark", creases);
    const BezierApproximation patches_set = approximation_patches(p);
  const std::vector<BezierPatch>& patches = patches_set.patches;
    const auto [distance, derivatives] = worst_against_exact(p, patches_set);
    CAPTURE(vertices);
    CHECK(distance < 1e-12);
    CHECK(derivatives < 1e-11);  // the tangent patches are the exact derivatives
    const EdgeSides e = compare_edges(p.surface->base(), patches);
    CHECK_FALSE(e.control_points_differ);
    CHECK(e.largest_position < 1e-14);
    CHECK(e.largest_tangent_angle < 1e-12);
  }
}

TEST_CASE("irregular boundaries: the boundary curves exact, C0 and one normal field inside, a tangent plane per "
          "boundary vertex") {
  // The plane with a square hole, made bumpy: the hole's corners have three faces.
  const test::Mesh holed = limit_test::bumpy_plane_with_hole();
  const PreparedEvaluation p = prepared(holed);
  const BezierApproximation patches_set = approximation_patches(p);
  const std::vector<BezierPatch>& patches = patches_set.patches;
  const Level& base = p.surface->base();
  // Along every boundary edge the patch is the exact limit curve (the boundary's cubic
  // B-spline), whatever the valences at its ends.
  const auto [faces, uv] = limit_test::boundary_edge_points(base, {0.0, 0.2, 0.5, 0.9, 1.0});
  CHECK(faces.size() == 5 * 24);  // 16 outer and 8 hole edges
  CHECK(approximate_points(p, patches_set, faces, uv).distances.largest < 1e-12);
  // Inside, the faces at the hole's corners only approximate.
  ApproximationDistances d;
  (void)approximated_limit_mesh(p, patches_set, 6, d);
  CHECK(d.largest > 1e-6);
  const EdgeSides e = compare_edges(base, patches);
  CHECK_FALSE(e.control_points_differ);
  CHECK(e.largest_position < 1e-14);
  CHECK(e.largest_tangent_angle < 1e-12);
  // At each boundary vertex, every face's tangent patches give the same normal.
  std::map<Index, std::vector<Point3>> normals;
  constexpr double corner_u[4] = {0, 1, 1, 0}, corner_v[4] = {0, 0, 1, 1};
  for (Index f = 0; f < base.face_count(); ++f)
    for (int k = 0; k < 4; ++k) {
      const Index v = base.face_vertices[size_t(4 * f + k)];
      if (!base.on_boundary(v)) continue;
      const PatchSample s = evaluate_patch(patches[size_t(f)], corner_u[k], corner_v[k]);
      normals[v].push_back(normal(s.du, s.dv));
    }
  double worst = 0;
  for (const auto& [v, list] : normals)
    for (const Point3& n : list) worst = std::max(worst, angle(n, list.front()));
  CHECK(worst < 1e-12);
  // And the exact limit's normal next to the vertex, at every boundary vertex that is some
  // face's corner 0: at (h, h) it converges to the vertex's tangent plane as h -> 0 —
  // linearly at regular boundary vertices; at the hole's corners (three faces, where the
  // masks are approximations before their projection) more slowly, but towards ours.
  const auto angle_at = [&](Index f, double h) {
    const std::vector<Index> at_face{f};
    const std::vector<double> near{h, h};
    const EvaluatedPoints exact = evaluate_limit_points(p, at_face, near, 1);
    const PatchSample s = evaluate_patch(patches[size_t(f)], 0, 0);
    return angle(normal(s.du, s.dv),
                 normal({exact.du[0], exact.du[1], exact.du[2]}, {exact.dv[0], exact.dv[1], exact.dv[2]}));
  };
  int hole_corners = 0;
  for (Index f = 0; f < base.face_count(); ++f) {
    const Index v = base.face_vertices[size_t(4 * f)];
    if (!base.on_boundary(v)) continue;
    CAPTURE(v);
    if (base.incident_face_count(v) < 3) {
      CHECK(angle_at(f, 1e-12) < 1e-10);
      continue;
    }
    ++hole_corners;
    const double far = angle_at(f, 1e-4), mid = angle_at(f, 1e-8), near = angle_at(f, 1e-12);
    MESSAGE("hole corner ", v, ": angle to the exact normal at h = 1e-4, 1e-8, 1e-12: ", far, ", ", mid, ", ", near);
    CHECK(mid < 0.2 * far);
    CHECK(near < 0.2 * mid);
    CHECK(near < 1e-3);
  }
  CHECK(hole_corners > 0);
}

TEST_CASE("what the boundary and crease masks do not cover is refused, naming the place") {
  const test::Mesh torus = test::torus(8, 6);
  // The cube's top square as a crease (vertices 4 to 7): the top face is one face on a side.
  const test::Mesh cube = test::cube();
  CHECK_THROWS_WITH_AS(
      approximation_patches(prepared(cube, "catmull-clark", creases_along(cube, [](Index a, Index b) { return a >= 4 && b >= 4; }))),
      doctest::Contains("only one face on a side"), Error);
  // The scheme's boundary curve must be the cubic B-spline: Catmull-Clark with four-point boundaries is refused.
  std::ifstream file(test::source_path("schemes/catmull-clark.json"));
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  text.replace(text.find("\"cubic-bspline\""), 15, "\"four-point\"");
  text.replace(text.find("\"catmull-clark\""), 15, "\"cc-four-point\"");
  const auto odd = load_scheme_text(text, "cc-four-point.json");
  CHECK(bezier_features_unsupported(load_scheme("catmull-clark"), {}).empty());
  CHECK(bezier_features_unsupported(odd, {}).find("phantom points") != std::string::npos);
}
