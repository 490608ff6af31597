// The approximating patches on meshes the masks do not read as they are: faces that are not
// quads (one step of the quad split makes quads) and semi-sharp creases and corners (ceil(s)
// steps let sharpness s decay; DeRose, Kass & Truong 1998). The patches are built on the
// refined level and evaluated at the base mesh's (face, u, v). Checked against the exact
// limit: where every vertex of the refined level is regular the patches are its bicubic
// B-spline patches, so the approximation is the limit itself; elsewhere every patch corner is
// a vertex of the refined level, whose limit point the corner takes (Loop & Schaefer 2008),
// and neighbouring faces meet along their shared edges. Holes remove faces, not rules: the
// kept faces have the patches of the mesh without the tags.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "framework/limit/face_domain.h"
#include "framework/pipeline/approximation_request.h"
#include "support/cli_checks.h"
#include "support/cli_runner.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"
#include "support/vtk_read.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

PreparedEvaluation prepared(const test::Mesh& m, std::vector<CreaseTag> creases = {},
                            std::vector<CornerTag> corners = {}) {
  EvaluateRequest r;
  r.mesh = test::mesh_data(m);
  r.mesh.creases = std::move(creases);
  r.mesh.corners = std::move(corners);
  r.scheme.text = "catmull-clark";
  return prepare_evaluation(std::move(r));
}

// The largest distance of the approximation from the exact limit at `points`, and the largest
// angle between their normals.
template <typename Patches>
std::pair<double, double> against_exact(const PreparedEvaluation& p, const Patches& patches,
                                        const limit_test::FacePoints& points) {
  const ApproximatedPoints a = approximate_points(p, patches, points.faces, points.uv);
  const EvaluatedPoints exact = evaluate_limit_points(p, points.faces, points.uv, 1);
  double angle = 0;
  for (size_t i = 0; i < points.faces.size(); ++i) {
    const auto n = limit_test::normal({exact.du[3 * i], exact.du[3 * i + 1], exact.du[3 * i + 2]},
                                      {exact.dv[3 * i], exact.dv[3 * i + 1], exact.dv[3 * i + 2]});
    angle = std::max(angle, limit_test::angle(n, {a.normals[3 * i], a.normals[3 * i + 1], a.normals[3 * i + 2]}));
  }
  return {a.distances.largest, angle};
}

// Semi-sharp tags on a regular torus: a crease loop of sharpness 2, a single edge of 1.5 (a
// dart at both ends until it decays) and a corner of 1.3.
PreparedEvaluation torus_with_semi_sharp_tags() {
  const test::Mesh torus = limit_test::bumpy(test::torus(8, 6));
  std::vector<CreaseTag> creases = limit_test::creases_along(torus, [](Index a, Index b) { return a / 8 == 0 && b / 8 == 0; });
  for (CreaseTag& c : creases) c.sharpness = 2;
  creases.push_back({27, 28, 1.5});
  return prepared(torus, creases, {{36, 1.3}});
}

// The base (face, u, v) of every vertex of the level `steps` quad splits make: the corners of
// the dyadic squares of side 2^-steps of a quad; a face that is not a quad is n sub-faces
// after the first step, each half a tile of Bfr's layout, split 2^(steps - 1) times a side.
limit_test::FacePoints dyadic_corners(const Level& base, int steps) {
  limit_test::FacePoints out;
  for (Index f = 0; f < base.face_count(); ++f) {
    const int n = base.face_size(f);
    const int tiles = n == 4 ? 1 : n, columns = sub_face_columns(n);
    const int m = n == 4 ? 1 << steps : 1 << (steps - 1);
    const double side = n == 4 ? 1.0 : 0.5;
    for (int t = 0; t < tiles; ++t)
      for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= m; ++j) {
          out.faces.push_back(f);
          out.uv.push_back((n == 4 ? 0 : t % columns) + side * i / m);
          out.uv.push_back((n == 4 ? 0 : t / columns) + side * j / m);
        }
  }
  return out;
}

// A pentagonal prism: two pentagons and five quads, bumped.
test::Mesh pentagonal_prism() {
  test::Mesh m;
  const double pi = std::acos(-1.0);
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 5; ++i) m.add_vertex(std::cos(2 * pi * i / 5), std::sin(2 * pi * i / 5), z);
  m.add_face({4, 3, 2, 1, 0});
  m.add_face({5, 6, 7, 8, 9});
  for (Index i = 0; i < 5; ++i) m.add_face({i, (i + 1) % 5, 5 + (i + 1) % 5, 5 + i});
  return limit_test::bumpy(m);
}

// The base (u, v) of the point at t <= 1/2 along edge k of face f (from corner k): in the
// first half of the edge, inside sub-face k of a face that is not a quad.
std::array<double, 2> edge_point(const Level& base, Index f, int k, double t) {
  const int n = base.face_size(f);
  if (n == 4) return limit_test::quad_edge_point(k, t);
  const int columns = sub_face_columns(n);
  return {k % columns + t, double(k / columns)};
}

// The same point from the other side, where it lies at 1 - t along edge k of face f: in
// sub-face k + 1 of a face that is not a quad, on its edge towards corner k + 1.
std::array<double, 2> edge_point_from_end(const Level& base, Index f, int k, double t) {
  const int n = base.face_size(f);
  if (n == 4) return limit_test::quad_edge_point(k, 1 - t);
  const int columns = sub_face_columns(n), next = (k + 1) % n;
  return {double(next % columns), next / columns + t};
}

// The largest gap between the two faces' approximations at t along every interior edge.
template <typename Patches>
double largest_gap_across_edges(const PreparedEvaluation& p, const Patches& patches, double t) {
  const Level& base = p.surface->base();
  const auto edges = limit_test::directed_edges(base);
  limit_test::FacePoints here, there;
  for (const auto& [ab, fk] : edges) {
    const auto other = edges.find({ab.second, ab.first});
    if (other == edges.end()) continue;
    const auto x = edge_point(base, fk.first, fk.second, t);
    const auto y = edge_point_from_end(base, other->second.first, other->second.second, t);
    here.faces.push_back(fk.first), here.uv.insert(here.uv.end(), x.begin(), x.end());
    there.faces.push_back(other->second.first), there.uv.insert(there.uv.end(), y.begin(), y.end());
  }
  REQUIRE(!here.faces.empty());
  const ApproximatedPoints a = approximate_points(p, patches, here.faces, here.uv);
  const ApproximatedPoints b = approximate_points(p, patches, there.faces, there.uv);
  return limit_test::distance(a.positions, b.positions);
}

}  // namespace

TEST_CASE("semi-sharp creases and corners: the patches of the level where they have decayed, the limit itself on a "
          "regular torus") {
  const PreparedEvaluation p = torus_with_semi_sharp_tags();
  const limit_test::FacePoints points = limit_test::random_face_points(400, p.surface->base().face_count(), 5);
  const BezierApproximation bezier = approximation_patches(p);
  const GregoryApproximation gregory = gregory_approximation_patches(p);
  CHECK(bezier.steps == 2);  // ceil(2): sharpness decays by one a step
  CHECK(gregory.steps == 2);
  CHECK(bezier.patches.size() == 16 * 48);
  for (Index f = 0; f < Index(bezier.patches.size()); ++f) CHECK(bezier.base_face[size_t(f)] < 48);
  // After the decay every vertex has valence 4 and no tag: B-spline patches, exact.
  const auto [distance, angle] = against_exact(p, bezier, points);
  CHECK(distance < 1e-12);
  CHECK(angle < 1e-10);
  const auto [g_distance, g_angle] = against_exact(p, gregory, points);
  CHECK(g_distance < 1e-12);
  CHECK(g_angle < 1e-10);
  // Before the decay the limit differs from the untagged one: the tags are not ignored.
  const PreparedEvaluation untagged = prepared(limit_test::bumpy(test::torus(8, 6)));
  CHECK(limit_test::distance(evaluate_limit_points(p, points.faces, points.uv, 0).position,
                             evaluate_limit_points(untagged, points.faces, points.uv, 0).position) > 1e-3);
}

TEST_CASE("semi-sharp creases on a cube: every patch corner at the exact limit, the patches meeting along every edge") {
  const test::Mesh cube = limit_test::bumpy(test::cube());
  std::vector<CreaseTag> top = limit_test::creases_along(cube, [](Index a, Index b) { return a >= 4 && b >= 4; });
  for (CreaseTag& c : top) c.sharpness = 1.5;  // one face on a side at the base: refused before it decays
  const PreparedEvaluation p = prepared(cube, top);
  const BezierApproximation bezier = approximation_patches(p);
  const GregoryApproximation gregory = gregory_approximation_patches(p);
  REQUIRE(bezier.steps == 2);
  const limit_test::FacePoints corners = dyadic_corners(p.surface->base(), 2);
  CHECK(approximate_points(p, bezier, corners.faces, corners.uv).distances.largest < 1e-12);
  CHECK(approximate_points(p, gregory, corners.faces, corners.uv).distances.largest < 1e-12);
  // Near the valence-3 corners they approximate.
  const limit_test::FacePoints points = limit_test::random_face_points(300, 6, 7);
  CHECK(approximate_points(p, bezier, points.faces, points.uv).distances.largest > 1e-5);
  for (double t : {0.2, 0.45}) {
    CHECK(largest_gap_across_edges(p, bezier, t) < 1e-13);
    CHECK(largest_gap_across_edges(p, gregory, t) < 1e-13);
  }
}

TEST_CASE("faces that are not quads: the patches of their sub-faces after one step, corners at the exact limit, C0 "
          "across every edge") {
  for (const test::Mesh& m : {limit_test::bumpy(test::pyramid()), pentagonal_prism()}) {
    const PreparedEvaluation p = prepared(m);
    const BezierApproximation bezier = approximation_patches(p);
    const GregoryApproximation gregory = gregory_approximation_patches(p);
    const Level& base = p.surface->base();
    REQUIRE(bezier.steps == 1);
    size_t corners_in_base = 0;
    for (Index f = 0; f < base.face_count(); ++f) corners_in_base += size_t(base.face_size(f));
    CHECK(bezier.patches.size() == corners_in_base);  // one sub-quad per corner
    // The base vertices, edge middles and face centres: the level-1 vertices.
    const limit_test::FacePoints level1 = dyadic_corners(base, 1);
    CHECK(approximate_points(p, bezier, level1.faces, level1.uv).distances.largest < 1e-12);
    CHECK(approximate_points(p, gregory, level1.faces, level1.uv).distances.largest < 1e-12);
    for (double t : {0.1, 0.3}) {
      CHECK(largest_gap_across_edges(p, bezier, t) < 1e-13);
      CHECK(largest_gap_across_edges(p, gregory, t) < 1e-13);
    }
  }
}

TEST_CASE("subdiv evaluate --approximate bezier on a mesh with triangles writes the sub-faces' patches") {
  const fs::path dir = test::fresh_dir("bezier-refined-cli");
  const std::string mesh = test::source_path("examples/meshes/pyramid.obj");
  const auto r = test::run_subdiv("evaluate " + mesh + " --approximate bezier --samples 4 -o " +
                                  (dir / "out.vtp").string() + " --bezier-net " + (dir / "net.vtu").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("bicubic patches (Loop & Schaefer 2008) against the exact limit") != std::string::npos);
  const auto poly = test::read_vtp(dir / "out.vtp");
  CHECK(poly->GetNumberOfCells() == 16 + 4 * 3 * 4);  // 4 x 4 on the quad, 2 x 2 on each triangle's sub-faces
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((dir / "net.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* net = reader->GetOutput();
  CHECK(net->GetNumberOfCells() == 4 + 4 * 3);  // the quad's four sub-quads, each triangle's three
  vtkDataArray* base_face = net->GetCellData()->GetArray("base_face");
  REQUIRE(base_face);
  for (vtkIdType c = 0; c < net->GetNumberOfCells(); ++c) CHECK(base_face->GetTuple1(c) <= 4);
  const auto g = test::run_subdiv("evaluate " + mesh + " --approximate gregory --samples 2 -o " + (dir / "g.vtp").string());
  CHECK_MESSAGE(g.exit_code == 0, g.output);
}

TEST_CASE("holes: the kept faces have the untagged mesh's patches, the hole's are neither sampled nor written") {
  const test::Mesh cube = limit_test::bumpy(test::cube());
  std::vector<CreaseTag> creases = {{0, 1, 1.5}};  // and a semi-sharp edge: patches two steps down
  EvaluateRequest r;
  r.mesh = test::mesh_data(cube);
  r.mesh.creases = creases;
  r.mesh.holes = {5};
  r.scheme.text = "catmull-clark";
  const PreparedEvaluation holed = prepare_evaluation(std::move(r));
  const PreparedEvaluation whole = prepared(cube, creases);
  const limit_test::FacePoints points = limit_test::random_face_points(200, 5, 3);  // faces 0-4, kept
  for (const bool gregory : {false, true}) {
    const auto positions = [&](const PreparedEvaluation& p) {
      return gregory ? approximate_points(p, gregory_approximation_patches(p), points.faces, points.uv).positions
                     : approximate_points(p, approximation_patches(p), points.faces, points.uv).positions;
    };
    CHECK(limit_test::distance(positions(holed), positions(whole)) == 0);
  }
  ApproximationDistances d;
  const MeshData sampled = approximated_limit_mesh(holed, approximation_patches(holed), 4, d);
  CHECK(sampled.face_count() == 5 * 16);
  CHECK(d.per_face[5] == 0);  // no samples
  CHECK_THROWS_AS(approximate_points(holed, approximation_patches(holed), std::vector<Index>{5},
                                     std::vector<double>{0.5, 0.5}),
                  Error);
  const std::string net = bezier_control_net_vtu(approximation_patches(holed), d.per_face);
  CHECK(net.find("NumberOfCells=\"80\"") != std::string::npos);  // 5 faces x 16 patches (two steps)
}

TEST_CASE("a sharpness that would put the patches millions deep is refused before any work") {
  // 9.5 decays after 10 steps: 6 x 4^10 patches on the cube.
  CHECK_THROWS_WITH_AS(approximation_patches(prepared(test::cube(), {{0, 1, 9.5}})),
                       doctest::Contains("would be built on level 10"), Error);
  CHECK_THROWS_WITH_AS(gregory_approximation_patches(prepared(test::cube(), {{0, 1, 9.5}})),
                       doctest::Contains("6.29e+06 patches"), Error);
  // The command line names its option.
  const fs::path dir = test::fresh_dir("bezier-too-deep");
  const fs::path mesh = dir / "cube.obj";
  std::ofstream(mesh) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                         "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\nt crease 2/1/0 0 1 9.5\n";
  test::check_refused("evaluate " + mesh.string() + " --approximate bezier --samples 2", dir / "out.vtp",
                      "--approximate bezier: the patches would be built on level 10");
}
