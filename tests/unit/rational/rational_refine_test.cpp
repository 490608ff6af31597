// Rational (homogeneous) subdivision (framework/pipeline/rational_weights.h): a weighted
// control mesh is refined as (w·p, w) by the scheme's own rules and projected. The checks:
// weights all 1 give the plain result bit for bit; the refined homogeneous coordinates are
// the plain refinement of (w·p, w); scaling every weight changes nothing projective; and a
// weighted net whose pieces are rational quadratic Bezier arcs lies on the circle / sphere
// (Piegl & Tiller 1997, "The NURBS Book", section 7.5: a circular arc of angle 2θ is the
// quadratic Bezier with weights 1, cos θ, 1 on its end points and the tangents' meeting point).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "framework/curve/curve_level.h"
#include "framework/curve/curve_refine.h"
#include "framework/io/mesh_data.h"
#include "framework/pipeline/rational_weights.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::mesh_data;

RefineRequest request_for(MeshData mesh, const std::string& scheme, int levels) {
  RefineRequest r;
  r.mesh = std::move(mesh);
  r.mesh_name = "test mesh";
  r.scheme.text = scheme;
  r.levels = levels;
  return r;
}

const DataArray& array_named(const std::vector<DataArray>& arrays, const std::string& name) {
  for (const DataArray& a : arrays)
    if (a.name == name) return a;
  FAIL("no array ", name);
  return arrays.front();
}

// Weights in [0.5, 2] that differ from vertex to vertex (a fixed, irregular pattern).
std::vector<double> some_weights(Index n) {
  std::vector<double> w(static_cast<size_t>(n));
  for (Index v = 0; v < n; ++v) w[size_t(v)] = 0.5 + 1.5 * std::fmod(0.618033988749895 * (v + 1), 1.0);
  return w;
}

MeshData weighted(const test::Mesh& m, std::vector<double> w, const std::string& name = "weight") {
  MeshData d = mesh_data(m);
  d.point_data.push_back({name, 1, std::move(w)});
  return d;
}

// A rational quadratic uniform B-spline's three control points (homogeneous x, y, w) whose
// one span is the quarter circle from (1, 0) to (0, 1): the span's Bezier points are the
// homogeneous edge midpoints and the middle point, so the middle point is the corner (1, 1)
// with weight cos 45°, and each end point is reflected through its Bezier end point.
std::vector<std::array<double, 3>> quarter_arc() {
  const double c = std::sqrt(0.5);
  const std::array<double, 3> b0{1, 0, 1}, b1{c, c, c}, b2{0, 1, 1};
  std::array<double, 3> h0{}, h2{};
  for (int i = 0; i < 3; ++i) h0[size_t(i)] = 2 * b0[size_t(i)] - b1[size_t(i)], h2[size_t(i)] = 2 * b2[size_t(i)] - b1[size_t(i)];
  return {h0, b1, h2};
}

}  // namespace

TEST_CASE("rational: all weights 1 give the plain refinement bit for bit") {
  for (const char* scheme : {"catmull-clark", "loop", "doo-sabin", "sqrt3", "modified-butterfly"}) {
    CAPTURE(scheme);
    const bool triangles = std::string(scheme) != "catmull-clark" && std::string(scheme) != "doo-sabin";
    const test::Mesh m = triangles ? test::bipyramid(5) : test::cube();
    const RefineResult plain = refine_mesh(request_for(mesh_data(m), scheme, 3));
    const RefineResult ones =
        refine_mesh(request_for(weighted(m, std::vector<double>(size_t(m.positions.size() / 3), 1.0)), scheme, 3));
    CHECK(ones.levels.back().positions == plain.levels.back().positions);
  }
}

TEST_CASE("rational: the homogeneous coordinates are the plain refinement of (w p, w)") {
  for (const char* scheme : {"catmull-clark", "loop", "doo-sabin", "butterfly"}) {
    CAPTURE(scheme);
    const bool triangles = std::string(scheme) == "loop" || std::string(scheme) == "butterfly";
    const test::Mesh m = triangles ? test::bipyramid(5) : test::cube();
    const Index n = Index(m.positions.size() / 3);
    const std::vector<double> w = some_weights(n);
    const RefineResult rational = refine_mesh(request_for(weighted(m, w), scheme, 3));
    // The plain refinement of the homogeneous points, with w as a plain point array.
    MeshData homogeneous = mesh_data(m);
    to_homogeneous(homogeneous.positions, w);
    homogeneous.point_data.push_back({"w", 1, w});
    const RefineResult plain = refine_mesh(request_for(std::move(homogeneous), scheme, 3));
    const std::vector<double>& W = array_named(rational.levels.back().point_data, "weight").values;
    const std::vector<double>& Wp = array_named(plain.levels.back().point_data, "w").values;
    REQUIRE(W.size() == Wp.size());
    double worst = 0;
    for (size_t v = 0; v < W.size(); ++v) {
      worst = std::max(worst, std::abs(W[v] - Wp[v]));
      for (size_t c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(rational.levels.back().positions[3 * v + c] * W[v] -
                                         plain.levels.back().positions[3 * v + c]));
    }
    CHECK(worst <= 1e-13);
  }
}

TEST_CASE("rational: scaling every weight leaves the projected points unchanged") {
  const test::Mesh m = test::cube();
  const std::vector<double> w = some_weights(8);
  std::vector<double> scaled = w;
  for (double& x : scaled) x *= 37.25;
  const RefineResult a = refine_mesh(request_for(weighted(m, w), "catmull-clark", 3));
  const RefineResult b = refine_mesh(request_for(weighted(m, scaled), "catmull-clark", 3));
  const auto& pa = a.levels.back().positions;
  const auto& pb = b.levels.back().positions;
  REQUIRE(pa.size() == pb.size());
  double worst = 0;
  for (size_t i = 0; i < pa.size(); ++i) worst = std::max(worst, std::abs(pa[i] - pb[i]));
  CHECK(worst <= 1e-14);
  // And the weights themselves scale.
  CHECK(array_named(b.levels.back().point_data, "weight").values[5] ==
        doctest::Approx(37.25 * array_named(a.levels.back().point_data, "weight").values[5]).epsilon(1e-14));
}

TEST_CASE("rational: non-positive weights and missing arrays are refused by name") {
  const test::Mesh m = test::cube();
  std::vector<double> w(8, 1.0);
  w[5] = 0;
  CHECK_THROWS_WITH_AS(refine_mesh(request_for(weighted(m, w), "catmull-clark", 1)),
                       doctest::Contains("vertex 5 (counted from 0) has the rational weight weight = 0"), Error);
  w[5] = -2;
  CHECK_THROWS_WITH_AS(refine_mesh(request_for(weighted(m, w), "catmull-clark", 1)), doctest::Contains("vertex 5"),
                       Error);
  RefineRequest named = request_for(weighted(m, std::vector<double>(8, 2.0), "rw"), "catmull-clark", 1);
  named.weights_array = "w";
  CHECK_THROWS_WITH_AS(refine_mesh(named), doctest::Contains("no point array 'w' holds the rational weights; its point arrays are 'rw'"),
                       Error);
  named.weights_array = "rw";
  CHECK(refine_mesh(named).levels.back().positions.size() == 3 * 26);
}

TEST_CASE("rational: four weighted quadratic B-spline arcs lie on the unit circle at every level") {
  // Chaikin with uniform ends (examples/rational/chaikin-uniform.json): an open polyline
  // refines to its uniform quadratic B-spline, whose one span per three points is the
  // quarter arc's Bezier. The curve passes through the homogeneous midpoints of every level's
  // edges (the limit of a Chaikin polygon at an edge's midpoint), so those lie on the circle.
  const auto scheme = load_curve(std::string(SUBDIV_SOURCE_DIR) + "/examples/rational/chaikin-uniform.json");
  MeshData mesh;
  std::vector<double> w;
  const auto arc = quarter_arc();
  for (int k = 0; k < 4; ++k) {
    const double a = k * M_PI / 2, ca = std::cos(a), sa = std::sin(a);
    for (const auto& h : arc) {
      const double x = h[0] / h[2], y = h[1] / h[2];
      mesh.positions.insert(mesh.positions.end(), {ca * x - sa * y, sa * x + ca * y, 0.0});
      w.push_back(h[2]);
      mesh.line_vertices.push_back(Index(w.size() - 1));
    }
    mesh.line_offsets.push_back(Index(mesh.line_vertices.size()));
  }
  CurveLevel level = curve_level_from_mesh(mesh, "arcs");
  std::vector<double> xyz = mesh.positions;
  to_homogeneous(xyz, w);
  for (int l = 1; l <= 5; ++l) {
    CAPTURE(l);
    CurveStep step = refine_curve_step(level, evaluate_curve_rules(*scheme, l - 1), scheme->name);
    xyz = step.stencils.apply(xyz, 3);
    w = step.stencils.apply(w, 1);
    level = std::move(step.child);
    double worst = 0;
    int checked = 0;
    for (Index p = 0; p < level.polyline_count(); ++p) {
      const auto points = level.polyline(p);
      for (size_t i = 0; i + 1 < points.size(); ++i) {
        const size_t a = size_t(points[i]), b = size_t(points[i + 1]);
        const double W = w[a] + w[b];
        const double x = (xyz[3 * a] + xyz[3 * b]) / W, y = (xyz[3 * a + 1] + xyz[3 * b + 1]) / W;
        worst = std::max(worst, std::abs(std::hypot(x, y) - 1));
        ++checked;
      }
    }
    CHECK(checked == 4 * ((1 << l) + 1));  // every span of every level: the whole arc
    CHECK(worst <= 1e-12);
  }
}

namespace {

// A 5 x 5 weighted net of the uniform biquadratic B-spline whose middle 3 x 3 points make
// one span per direction: the tensor product (x(u) a(v), x(u) b(v), z(u)) of the quarter arc
// as meridian (x, z) and as circle of revolution (a, b), i.e. the sphere's first octant. The
// outer ring extends each arc linearly in homogeneous coordinates (any positive weights
// would do: it only keeps Doo-Sabin's boundary rules away from the octant).
struct Net {
  MeshData mesh;         // projected points, faces, weights "weight"
  MeshData parameters;   // the same faces at (i, j, 0): the B-spline's parameter plane
};

Net octant_net() {
  auto arc = quarter_arc();
  std::array<double, 3> before{}, after{};
  for (size_t i = 0; i < 3; ++i) before[i] = 2 * arc[0][i] - arc[1][i], after[i] = 2 * arc[2][i] - arc[1][i];
  arc.insert(arc.begin(), before);
  arc.push_back(after);
  Net net;
  std::vector<double> w;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const auto& m = arc[size_t(i)];  // meridian: (x w, z w, w)
      const auto& r = arc[size_t(j)];  // revolution: (a w', b w', w')
      const double W = m[2] * r[2];
      net.mesh.positions.insert(net.mesh.positions.end(), {m[0] * r[0] / W, m[0] * r[1] / W, m[1] * r[2] / W});
      w.push_back(W);
      net.parameters.positions.insert(net.parameters.positions.end(), {double(i), double(j), 0.0});
    }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const Index q[4] = {Index(5 * i + j), Index(5 * i + j + 1), Index(5 * (i + 1) + j + 1), Index(5 * (i + 1) + j)};
      for (MeshData* d : {&net.mesh, &net.parameters}) {
        d->face_vertices.insert(d->face_vertices.end(), q, q + 4);
        d->face_offsets.push_back(Index(d->face_vertices.size()));
      }
    }
  net.mesh.point_data.push_back({"weight", 1, std::move(w)});
  return net;
}

// Whether a point of the parameter plane lies in the octant's span (centroids of the faces
// around the middle vertex (2, 2) at 1.5 and 2.5), with a margin.
bool in_octant_span(const double* uv) {
  const double e = 1e-9;
  return uv[0] >= 1.5 - e && uv[0] <= 2.5 + e && uv[1] >= 1.5 - e && uv[1] <= 2.5 + e;
}

}  // namespace

TEST_CASE("rational: a weighted Doo-Sabin net draws the sphere's octant exactly at levels 1-5") {
  // Doo-Sabin is the biquadratic B-spline on regular quads (Doo & Sabin 1978): each face
  // centroid of a level, in homogeneous coordinates, is the spline at a knot. The parameter
  // mesh (plain, linear precision) says where each face sits in the parameter plane.
  const Net net = octant_net();
  for (int l = 1; l <= 5; ++l) {
    CAPTURE(l);
    const RefineResult sphere = refine_mesh(request_for(net.mesh, "doo-sabin", l));
    const RefineResult plane = refine_mesh(request_for(net.parameters, "doo-sabin", l));
    const Level& fine = sphere.hierarchy.levels.back();
    const auto& P = sphere.levels.back().positions;
    const auto& W = array_named(sphere.levels.back().point_data, "weight").values;
    const auto& uv = plane.levels.back().positions;
    double worst = 0;
    int checked = 0;
    for (Index f = 0; f < fine.face_count(); ++f) {
      double h[4] = {0, 0, 0, 0}, c[3] = {0, 0, 0};
      const auto corners = fine.face(f);
      for (Index v : corners) {
        for (size_t k = 0; k < 3; ++k) h[k] += P[3 * size_t(v) + k] * W[size_t(v)], c[k] += uv[3 * size_t(v) + k] / double(corners.size());
        h[3] += W[size_t(v)];
      }
      if (!in_octant_span(c)) continue;
      worst = std::max(worst, std::abs(std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]) / h[3] - 1));
      ++checked;
    }
    CHECK(checked == ((1 << l) + 1) * ((1 << l) + 1));  // the whole span: a knot grid of 2^l + 1 per side
    CHECK(worst <= 1e-12);
  }
}

TEST_CASE("rational: limit positions and normals of the weighted net are the sphere's") {
  // The limit of a vertex is projected after the linear mask, its tangents by the quotient
  // rule; on the unit sphere the normal at p is ±p.
  const Net net = octant_net();
  RefineRequest r = request_for(net.mesh, "doo-sabin", 2);
  r.limit_positions = true;
  const RefineResult sphere = refine_mesh(r);
  RefineRequest q = request_for(net.parameters, "doo-sabin", 2);
  q.limit_positions = true;
  const RefineResult plane = refine_mesh(q);
  const auto& P = sphere.levels.back().positions;
  const auto& uv = plane.levels.back().positions;
  const auto& N = array_named(sphere.finest_point_data, "normal").values;
  const auto& exact = array_named(sphere.finest_point_data, "normal_exact").values;
  double worst_p = 0, worst_n = 0;
  int checked = 0;
  for (size_t v = 0; v < P.size() / 3; ++v) {
    if (!in_octant_span(&uv[3 * v]) || exact[v] != 1) continue;
    const double* p = &P[3 * v];
    const double* n = &N[3 * v];
    worst_p = std::max(worst_p, std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1));
    const double cross[3] = {p[1] * n[2] - p[2] * n[1], p[2] * n[0] - p[0] * n[2], p[0] * n[1] - p[1] * n[0]};
    worst_n = std::max(worst_n, std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]));
    ++checked;
  }
  CHECK(checked >= 16);
  CHECK(worst_p <= 1e-12);
  CHECK(worst_n <= 1e-12);
  // Without the quotient rule the normals would be those of the homogeneous points' first
  // three coordinates: check that they differ, so the test above can fail.
  RefineRequest homogeneous = request_for(net.mesh, "doo-sabin", 2);
  to_homogeneous(homogeneous.mesh.positions, homogeneous.mesh.point_data[0].values);
  homogeneous.mesh.point_data.clear();
  homogeneous.limit_normals = true;
  const RefineResult wrong = refine_mesh(homogeneous);
  const auto& Nw = array_named(wrong.finest_point_data, "normal").values;
  double differs = 0;
  for (size_t i = 0; i < Nw.size(); ++i) differs = std::max(differs, std::abs(Nw[i] - N[i]));
  CHECK(differs > 1e-3);
}

}  // namespace subdiv

#include "unit/plugins/plugin_test_support.h"

namespace subdiv {

TEST_CASE("rational: a plugin's linear C++ rules refine (w p, w) too; a non-linear rule is refused") {
  test::load_example_plugins();
  const test::Mesh m = test::grid(4, 4);
  const std::vector<double> w = some_weights(25);
  const RefineResult rational = refine_mesh(request_for(weighted(m, w), "kobbelt-quad", 2));
  MeshData homogeneous = mesh_data(m);
  to_homogeneous(homogeneous.positions, w);
  homogeneous.point_data.push_back({"w", 1, w});
  const RefineResult plain = refine_mesh(request_for(std::move(homogeneous), "kobbelt-quad", 2));
  const auto& W = array_named(rational.levels.back().point_data, "weight").values;
  const auto& Wp = array_named(plain.levels.back().point_data, "w").values;
  REQUIRE(W.size() == Wp.size());
  double worst = 0;
  for (size_t v = 0; v < W.size(); ++v) {
    worst = std::max(worst, std::abs(W[v] - Wp[v]));
    for (size_t c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(rational.levels.back().positions[3 * v + c] * W[v] - plain.levels.back().positions[3 * v + c]));
  }
  CHECK(worst <= 1e-13);
  CHECK_THROWS_WITH_AS(refine_mesh(request_for(weighted(m, w), "circle-quad", 1)),
                       doctest::Contains("need a linear scheme"), Error);
}

}  // namespace subdiv
