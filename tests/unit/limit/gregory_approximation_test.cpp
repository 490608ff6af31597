// Loop, Schaefer, Ni & Castaño's (2009) Gregory patches against properties of the
// construction and the exact limit: the bicubic B-spline patch reproduced where every
// valence is 4, the corners and their tangent planes the exact limit's, one boundary curve
// per edge (no cracks) and one normal across every edge (G1, where Loop & Schaefer's 2008
// geometry patches are not), and the distance to the exact limit beside the Bézier mode's.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/pipeline/approximation_request.h"
#include "framework/util/error.h"
#include "support/cli_checks.h"
#include "support/cli_runner.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"
#include "support/vtk_read.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;
using limit_test::angle;
using limit_test::normal;
using limit_test::quad_split;

namespace {

PreparedEvaluation prepared(const test::Mesh& m, std::vector<CreaseTag> creases = {}) {
  EvaluateRequest r;
  r.mesh = test::mesh_data(m);
  r.mesh.creases = std::move(creases);
  r.scheme.text = "catmull-clark";
  return prepare_evaluation(std::move(r));
}

// Closed quad meshes with vertices of valence 3, 4, 5 and 6 (limit/bezier_approximation_test.cpp).
std::vector<test::Mesh> irregular_meshes() {
  return {test::cube(), quad_split(test::bipyramid(5)), quad_split(test::bipyramid(6))};
}

struct EdgeSides {
  double largest_position = 0, largest_angle = 0;
};

// Along every edge, both faces' samples at the same points: the largest difference of the
// positions and the largest angle between the normals.
template <typename Sample>
EdgeSides compare_edges(const Level& level, const Sample& sample) {
  const auto directed = limit_test::directed_quad_edges(level);
  EdgeSides out;
  for (const auto& [e, fk] : directed) {
    if (!directed.contains({e.second, e.first})) continue;  // a boundary edge: one side only
    const auto& [g, l] = directed.at({e.second, e.first});
    // Across an infinitely sharp crease the normal may jump: positions only.
    const bool crease = level.edge_sharp(level.face_edges[size_t(4 * fk.first + fk.second)]) > 0;
    for (double t : {0.0, 0.05, 0.1, 0.37, 0.5, 0.81, 0.95, 1.0}) {
      const auto a = limit_test::quad_edge_point(fk.second, t), b = limit_test::quad_edge_point(l, 1 - t);
      const PatchSample p = sample(fk.first, a[0], a[1]), q = sample(g, b[0], b[1]);
      for (size_t c = 0; c < 3; ++c)
        out.largest_position = std::max(out.largest_position, std::abs(p.position[c] - q.position[c]));
      if (!crease)
        out.largest_angle = std::max(out.largest_angle,
                                     angle(normal(p.geometry_du, p.geometry_dv), normal(q.geometry_du, q.geometry_dv)));
    }
  }
  return out;
}

bool all_valence_4(const Level& base, Index f) {
  for (int k = 0; k < 4; ++k) {
    const Index v = base.face_vertices[size_t(4 * f + k)];
    if (base.vertex_ring_offsets[size_t(v) + 1] - base.vertex_ring_offsets[size_t(v)] != 4) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("where every valence is 4 the Gregory patches are the exact limit (the bicubic B-spline)") {
  const PreparedEvaluation p = prepared(test::torus(6, 5));
  const GregoryApproximation patches_set = gregory_approximation_patches(p);
  const std::vector<GregoryPatch>& patches = patches_set.patches;
  const auto [faces, uv] = limit_test::random_face_points(200, 30, 11);
  CHECK(approximate_points(p, patches_set, faces, uv).distances.largest < 1e-12);
  const EvaluatedPoints exact = evaluate_limit_points(p, faces, uv, 1);
  double derivatives = 0;  // the rational blends' derivatives included
  for (size_t i = 0; i < faces.size(); ++i) {
    const PatchSample s = evaluate_gregory(patches[size_t(faces[i])], uv[2 * i], uv[2 * i + 1]);
    for (size_t c = 0; c < 3; ++c)
      derivatives = std::max({derivatives, std::abs(s.du[c] - exact.du[3 * i + c]), std::abs(s.dv[c] - exact.dv[3 * i + c])});
  }
  CHECK(derivatives < 1e-11);
}

TEST_CASE("the Gregory patches' derivatives are those of their positions (central differences)") {
  const PreparedEvaluation p = prepared(test::cube());
  const GregoryApproximation patches_set = gregory_approximation_patches(p);
  const std::vector<GregoryPatch>& patches = patches_set.patches;
  constexpr double h = 1e-6;
  double worst = 0;
  for (const auto& uv : {std::array{0.3, 0.6}, std::array{0.02, 0.9}, std::array{0.5, 0.5}, std::array{0.97, 0.01}})
    for (Index f = 0; f < 6; ++f) {
      const auto at = [&](double u, double v) { return evaluate_gregory(patches[size_t(f)], u, v); };
      const PatchSample s = at(uv[0], uv[1]);
      for (size_t c = 0; c < 3; ++c) {
        worst = std::max(worst, std::abs((at(uv[0] + h, uv[1]).position[c] - at(uv[0] - h, uv[1]).position[c]) / (2 * h) - s.du[c]));
        worst = std::max(worst, std::abs((at(uv[0], uv[1] + h).position[c] - at(uv[0], uv[1] - h).position[c]) / (2 * h) - s.dv[c]));
      }
    }
  CHECK(worst < 1e-7);
}

TEST_CASE("Gregory patches share their boundary curves and one normal across every edge, where the Bézier geometry "
          "patches' normals jump") {
  for (const test::Mesh& m : irregular_meshes()) {
    const PreparedEvaluation p = prepared(m);
    const GregoryApproximation gregory_set = gregory_approximation_patches(p);
  const std::vector<GregoryPatch>& gregory = gregory_set.patches;
    const BezierApproximation bezier_set = approximation_patches(p);
    const std::vector<BezierPatch>& bezier = bezier_set.patches;
    const EdgeSides g = compare_edges(
        p.surface->base(), [&](Index f, double u, double v) { return evaluate_gregory(gregory[size_t(f)], u, v); });
    const EdgeSides b = compare_edges(
        p.surface->base(), [&](Index f, double u, double v) { return evaluate_patch(bezier[size_t(f)], u, v); });
    MESSAGE("largest normal angle across edges: Gregory ", g.largest_angle, ", Bezier geometry ", b.largest_angle);
    CHECK(g.largest_position < 1e-14);  // evaluated from both sides: round-off only
    CHECK(g.largest_angle < 1e-12);
    CHECK(b.largest_angle > 1e-3);
  }
}

TEST_CASE("the Gregory patches' corners are the limit positions, with the limit's tangent plane") {
  for (const test::Mesh& m : irregular_meshes()) {
    const PreparedEvaluation p = prepared(m);
    const GregoryApproximation patches_set = gregory_approximation_patches(p);
  const std::vector<GregoryPatch>& patches = patches_set.patches;
    const Level& base = p.surface->base();
    double position = 0, normal_angle = 0;
    for (Index f = 0; f < base.face_count(); ++f)
      for (const auto& corner : {std::array{0.0, 0.0}, std::array{1.0, 0.0}, std::array{1.0, 1.0}, std::array{0.0, 1.0}}) {
        // The exact normal approaches the vertex's as h -> 0 (linearly: the limit is C1 there).
        const auto towards = [](double x) { return x == 0 ? 1e-60 : 1 - 1e-16; };
        const std::vector<Index> faces{f};
        const std::vector<double> uv{towards(corner[0]), towards(corner[1])};
        const EvaluatedPoints exact = evaluate_limit_points(p, faces, uv, 1);
        const PatchSample s = evaluate_gregory(patches[size_t(f)], corner[0], corner[1]);
        for (size_t c = 0; c < 3; ++c) position = std::max(position, std::abs(s.position[c] - exact.position[c]));
        const Point3 du{exact.du[0], exact.du[1], exact.du[2]}, dv{exact.dv[0], exact.dv[1], exact.dv[2]};
        normal_angle = std::max(normal_angle, angle(normal(s.du, s.dv), normal(du, dv)));
      }
    MESSAGE("largest distance and normal angle to the exact limit at a corner: ", position, ", ", normal_angle);
    CHECK(position < 1e-13);
    CHECK(normal_angle < 1e-7);
  }
}

TEST_CASE("the Gregory patches' distance to the exact limit: 0 on regular faces, positive next to extraordinary "
          "vertices, of the Bézier patches' magnitude") {
  for (const test::Mesh& m : irregular_meshes()) {
    // Split twice more: faces away from the extraordinary vertices are regular.
    const PreparedEvaluation p = prepared(quad_split(quad_split(m)));
    const GregoryApproximation patches_set = gregory_approximation_patches(p);
  const std::vector<GregoryPatch>& patches = patches_set.patches;
    ApproximationDistances g, b;
    (void)approximated_limit_mesh(p, patches_set, 6, g);
    (void)approximated_limit_mesh(p, approximation_patches(p), 6, b);
    const Level& base = p.surface->base();
    int regular = 0, irregular = 0;
    for (Index f = 0; f < base.face_count(); ++f) {
      const bool all4 = all_valence_4(base, f);
      (all4 ? regular : irregular) += 1;
      if (all4) CHECK(g.per_face[size_t(f)] < 1e-12);
      else CHECK(g.per_face[size_t(f)] > 1e-6);
    }
    CHECK(regular > 0);
    CHECK(irregular > 0);
    MESSAGE("largest, mean: Gregory ", g.largest, ", ", g.mean, "; Bezier ", b.largest, ", ", b.mean);
    CHECK(g.largest < 4 * b.largest);
    CHECK(g.largest > 0.25 * b.largest);
  }
}

TEST_CASE("Gregory patches at boundaries, infinitely sharp creases and corners: the exact limit where every sector "
          "is regular, G1 across every other edge") {
  // An open grid: corners of one face (kept), boundary vertices with two faces, valence 4 inside.
  const test::Mesh grid = limit_test::bumpy(test::grid(6, 5));
  // A torus with two crease loops (rings v = 0 and v = 3 of 6): two faces on each side.
  const test::Mesh torus = test::torus(8, 6);
  const auto loops =
      limit_test::creases_along(torus, [](Index a, Index b) { return a / 8 == b / 8 && (a / 8 == 0 || a / 8 == 3); });
  // The cube with all 12 edges infinitely sharp: three crease edges at each corner, one face
  // between them; the limit is the cube itself.
  const test::Mesh cube = test::cube();
  const auto edges = limit_test::creases_along(cube, [](Index, Index) { return true; });
  for (const auto& [mesh, creases] : {std::pair{grid, std::vector<CreaseTag>{}}, std::pair{torus, loops},
                                      std::pair{cube, edges}}) {
    const Index vertices = mesh.vertex_count;  // clang 14: no structured binding in CAPTURE
    CAPTURE(vertices);
    const PreparedEvaluation p = prepared(mesh, creases);
    const GregoryApproximation patches_set = gregory_approximation_patches(p);
  const std::vector<GregoryPatch>& patches = patches_set.patches;
    ApproximationDistances d;
    (void)approximated_limit_mesh(p, patches_set, 6, d);
    CHECK(d.largest < 1e-12);
    const EdgeSides e = compare_edges(
        p.surface->base(), [&](Index f, double u, double v) { return evaluate_gregory(patches[size_t(f)], u, v); });
    CHECK(e.largest_position < 1e-14);
    CHECK(e.largest_angle < 1e-12);
  }
  // The plane with a square hole: the hole's corners have three faces. The boundary curves are
  // the exact limit's, the patches meet with G1 inside, and the faces at the hole's corners
  // only approximate.
  const PreparedEvaluation p = prepared(limit_test::bumpy_plane_with_hole());
  const GregoryApproximation patches_set = gregory_approximation_patches(p);
  const std::vector<GregoryPatch>& patches = patches_set.patches;
  const Level& base = p.surface->base();
  const auto [faces, uv] = limit_test::boundary_edge_points(base, {0.0, 0.2, 0.5, 0.9, 1.0});
  CHECK(faces.size() == 5 * 24);  // 16 outer and 8 hole edges
  CHECK(approximate_points(p, patches_set, faces, uv).distances.largest < 1e-12);
  ApproximationDistances d, bezier;
  (void)approximated_limit_mesh(p, patches_set, 6, d);
  (void)approximated_limit_mesh(p, approximation_patches(p), 6, bezier);
  MESSAGE("plane with a hole: largest, mean: Gregory ", d.largest, ", ", d.mean, "; Bezier ", bezier.largest, ", ",
          bezier.mean);
  CHECK(d.largest > 1e-6);
  CHECK(d.largest < 4 * bezier.largest);
  const EdgeSides e =
      compare_edges(base, [&](Index f, double u, double v) { return evaluate_gregory(patches[size_t(f)], u, v); });
  CHECK(e.largest_position < 1e-14);
  CHECK(e.largest_angle < 1e-12);
}

TEST_CASE("darts take the smooth vertex's masks: corners and tangent planes the limit's, C0 everywhere, G1 off the "
          "crease") {
  // A crease of two infinitely sharp edges ending inside a bumpy torus: vertices 0 and 2 are darts.
  const PreparedEvaluation p = prepared(limit_test::bumpy(test::torus(8, 6)), {{0, 1, 10}, {1, 2, 10}});
  const Level& base = p.surface->base();
  const GregoryApproximation gregory = gregory_approximation_patches(p);
  const BezierApproximation bezier = approximation_patches(p);
  limit_test::FacePoints corners;
  for (Index f = 0; f < base.face_count(); ++f)
    for (const auto& [u, v] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}})
      corners.faces.push_back(f), corners.uv.push_back(u), corners.uv.push_back(v);
  CHECK(approximate_points(p, gregory, corners.faces, corners.uv).distances.largest < 1e-12);
  CHECK(approximate_points(p, bezier, corners.faces, corners.uv).distances.largest < 1e-12);
  const EdgeSides g = compare_edges(
      base, [&](Index f, double u, double v) { return evaluate_gregory(gregory.patches[size_t(f)], u, v); });
  CHECK(g.largest_position < 1e-14);
  CHECK(g.largest_angle < 1e-12);  // across every edge but the crease's
  // The Bézier mode's normals are its tangent patches' (compared in place of the geometry's).
  const EdgeSides b = compare_edges(base, [&](Index f, double u, double v) {
    PatchSample s = evaluate_patch(bezier.patches[size_t(f)], u, v);
    s.geometry_du = s.du, s.geometry_dv = s.dv;
    return s;
  });
  CHECK(b.largest_position < 1e-14);
  CHECK(b.largest_angle < 1e-12);
  // At the darts the patches' normal is the limit's (its limit masks' tangent plane, Halstead,
  // Kass & DeRose 1993), from every face.
  LimitOptions options;
  const LimitResult limits = limit_positions(*p.scheme, base, p.mesh.positions, options);
  int dart_corners = 0;
  for (Index dart : {Index(0), Index(2)}) {
    REQUIRE(limits.normal_exact[size_t(dart)]);
    const std::array<double, 3> exact{limits.normals[3 * size_t(dart)], limits.normals[3 * size_t(dart) + 1],
                                      limits.normals[3 * size_t(dart) + 2]};
    for (Index f = 0; f < base.face_count(); ++f)
      for (int k = 0; k < 4; ++k) {
        if (base.face_vertices[size_t(4 * f + k)] != dart) continue;
        const auto uv = limit_test::quad_edge_point(k, 0.0);
        const PatchSample s = evaluate_gregory(gregory.patches[size_t(f)], uv[0], uv[1]);
        CHECK(angle(normal(s.geometry_du, s.geometry_dv), exact) < 1e-10);
        ++dart_corners;
      }
  }
  CHECK(dart_corners == 8);
  ApproximationDistances dg, db;
  (void)approximated_limit_mesh(p, gregory, 6, dg);
  (void)approximated_limit_mesh(p, bezier, 6, db);
  MESSAGE("torus with a dart: largest, mean distance: Gregory ", dg.largest, ", ", dg.mean, "; Bezier ", db.largest,
          ", ", db.mean);
}

TEST_CASE("corners of several faces: boundary curves exact, C0 everywhere, G1 across every inner edge") {
  // The plane with a square hole, its hole's corners (three faces each, concave) and a vertex
  // of its straight outer boundary (two faces) tagged as corners; and a triangulated grid
  // split into quads, whose corner vertices with two quads (convex) are tagged.
  const test::Mesh hole = limit_test::bumpy_plane_with_hole();
  const test::Mesh split = limit_test::bumpy(quad_split(test::grid(3, 3, true)));
  std::vector<CornerTag> hole_corners, split_corners;
  for (Index v : {Index(6), Index(8), Index(16), Index(18), Index(5)}) hole_corners.push_back({v, 10});
  const Level split_level = prepare_evaluation([&] {
                              EvaluateRequest r;
                              r.mesh = test::mesh_data(split);
                              r.scheme.text = "catmull-clark";
                              return r;
                            }()).surface->base();
  for (Index v = 0; v < split_level.vertex_count; ++v)
    if (split_level.on_boundary(v) && split_level.incident_face_count(v) == 2 &&
        std::abs(split.positions[3 * size_t(v)] - 1.5) == 1.5 && std::abs(split.positions[3 * size_t(v) + 1] - 1.5) == 1.5)
      split_corners.push_back({v, 10});
  REQUIRE(split_corners.size() == 2);  // the two grid corners the diagonals leave with two triangles
  for (const auto& [mesh, corners] : {std::pair{hole, hole_corners}, std::pair{split, split_corners}}) {
    EvaluateRequest r;
    r.mesh = test::mesh_data(mesh);
    r.mesh.corners = corners;
    r.scheme.text = "catmull-clark";
    const PreparedEvaluation p = prepare_evaluation(std::move(r));
    const Level& base = p.surface->base();
    const GregoryApproximation gregory = gregory_approximation_patches(p);
    const BezierApproximation bezier = approximation_patches(p);
    const auto [faces, uv] = limit_test::boundary_edge_points(base, {0.0, 0.2, 0.5, 0.9, 1.0});
    CHECK(approximate_points(p, gregory, faces, uv).distances.largest < 1e-12);
    CHECK(approximate_points(p, bezier, faces, uv).distances.largest < 1e-12);
    const EdgeSides g = compare_edges(
        base, [&](Index f, double u, double v) { return evaluate_gregory(gregory.patches[size_t(f)], u, v); });
    CHECK(g.largest_position < 1e-14);
    CHECK(g.largest_angle < 1e-12);
    const EdgeSides b = compare_edges(base, [&](Index f, double u, double v) {
      PatchSample s = evaluate_patch(bezier.patches[size_t(f)], u, v);
      s.geometry_du = s.du, s.geometry_dv = s.dv;  // the tangent patches' normal
      return s;
    });
    CHECK(b.largest_position < 1e-14);
    CHECK(b.largest_angle < 1e-12);
    ApproximationDistances dg, db;
    (void)approximated_limit_mesh(p, gregory, 6, dg);
    (void)approximated_limit_mesh(p, bezier, 6, db);
    MESSAGE(base.vertex_count, " vertices, corners of several faces: largest, mean distance: Gregory ", dg.largest,
            ", ", dg.mean, "; Bezier ", db.largest, ", ", db.mean);
  }
}

TEST_CASE("what the Gregory patches do not cover is refused, naming the place") {
  const test::Mesh torus = test::torus(6, 5);
  // The cube's top square as an infinitely sharp crease keeps a crease vertex with one face on
  // a side at every level; with a semi-sharp edge below, the refusal names the refined level.
  const test::Mesh cube = test::cube();
  std::vector<CreaseTag> creases = limit_test::creases_along(cube, [](Index a, Index b) { return a >= 4 && b >= 4; });
  creases.push_back({0, 1, 1.5});
  CHECK_THROWS_WITH_AS(gregory_approximation_patches(prepared(cube, creases)),
                       doctest::Contains("on level 2 (the mesh refined 2 times"), Error);
  CHECK_THROWS_WITH_AS(gregory_approximation_patches(prepared(cube, creases)),
                       doctest::Contains("only one face on a side"), Error);
  (void)torus;
}

TEST_CASE("subdiv evaluate --approximate gregory writes the patches, their normals and distances") {
  const std::filesystem::path dir = test::fresh_dir("gregory-cli");
  const std::string mesh = test::source_path("examples/meshes/cube.obj");
  const auto r = test::run_subdiv("evaluate " + mesh + " --approximate gregory --samples 4 -o " + (dir / "out.vtp").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  EvaluateRequest request;
  request.mesh_file = mesh;
  request.scheme.text = "catmull-clark";
  const PreparedEvaluation p = prepare_evaluation(std::move(request));
  ApproximationDistances d;
  (void)approximated_limit_mesh(p, gregory_approximation_patches(p), 4, d);
  CHECK(r.output.find(approximation_summary(d, ApproximationKind::Gregory)) != std::string::npos);
  const auto poly = test::read_vtp(dir / "out.vtp");
  CHECK(poly->GetNumberOfCells() == 6 * 16);
  CHECK(poly->GetPointData()->GetArray("limit_distance") != nullptr);
  CHECK(poly->GetPointData()->GetNormals() != nullptr);
  test::check_refused("evaluate " + mesh + " --approximate gregory --samples 4 --bezier-net " + (dir / "n.vtu").string(),
                      dir / "a.vtp", "--bezier-net goes with --approximate bezier");
  test::check_refused("evaluate " + test::source_path("examples/meshes/cube-creased.obj") +
                          " --approximate gregory --samples 4",
                      dir / "b.vtp", "vertex 0 is a corner inside the surface");
}
