// The generic method: limit masks from each scheme's eigen-analysis checked against the
// papers' closed forms (written out by hand in closed_form_limits.h), their selection by
// l S = l, Chen et al.'s progressive interpolation on plain Catmull-Clark, Loop, sqrt(3),
// user schemes, features, dual schemes, and the refusals.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>

#include "closed_form_limits.h"
#include "framework/interpolation/analysed_limit.h"
#include "framework/interpolation/dual_limits.h"
#include "framework/interpolation/interpolatory_limit.h"
#include "framework/interpolation/limit_selection.h"
#include "framework/interpolation/progressive.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "interp_reference.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// Loop 1987's limit: gamma_n v + (1 - gamma_n) mean(e), gamma_n = 3 / (11 - 8 beta_bar_n),
// beta_bar_n = 3/8 + (3/8 + cos(2 pi/n)/4)^2.
P3 loop_limit_point(const Level& L, const std::vector<double>& x, Index v) {
  const int n = L.valence(v);
  const double c = 3.0 / 8 + std::cos(2 * std::numbers::pi / n) / 4, beta_bar = 3.0 / 8 + c * c;
  const double gamma = 3.0 / (11 - 8 * beta_bar);
  P3 s = gamma * at(x, v);
  for (Index e : L.ring_edges(v)) s = s + ((1 - gamma) / n) * at(x, L.other_end(e, v));
  return s;
}

LimitChoice choose(const std::string& scheme, const Level& L, const ParameterOverrides& p = {}) {
  return select_limit(load_scheme_sequence(scheme, 1, p), L);
}
LimitChoice choose(const std::string& scheme, const Mesh& m, const ParameterOverrides& p = {}) {
  return choose(scheme, m.level(), p);
}

// The largest difference between two limit operators, weight by weight.
double max_row_difference(const StencilTable& a, const StencilTable& b) {
  REQUIRE(a.row_count() == b.row_count());
  double worst = 0;
  for (Index r = 0; r < a.row_count(); ++r) {
    std::map<Index, double> w;
    for (Index i = a.offsets[r]; i < a.offsets[r + 1]; ++i) w[a.indices[i]] += a.weights[i];
    for (Index i = b.offsets[r]; i < b.offsets[r + 1]; ++i) w[b.indices[i]] -= b.weights[i];
    for (const auto& [s, d] : w) worst = std::max(worst, std::abs(d));
  }
  return worst;
}

// The analysed operator a scheme gets on a level (after the l S = l check).
StencilTable analysed(const std::string& scheme, const Level& L, const ParameterOverrides& p = {}) {
  const LimitChoice c = choose(scheme, L, p);
  REQUIRE(dynamic_cast<const AnalysedLimit*>(c.evaluator.get()) != nullptr);
  return c.evaluator->limit_stencils(L);
}

// Vertex points after `levels` steps approach the limit: the distance falls geometrically.
void check_refinement_approaches(const std::string& scheme, const Level& L, const std::vector<double>& x,
                                 const StencilTable& limit) {
  const std::vector<double> l = limit.apply(x, 3);
  RefineOptions o;
  o.levels = 7;
  const Hierarchy h = refine(*load_scheme(scheme), L, o);
  std::vector<std::vector<double>> points{x};
  for (const auto& s : h.stencils) points.push_back(s.apply(points.back(), 3));
  Hierarchy two = h, seven = h;
  two.levels.resize(3), two.origins.resize(2), two.stencils.resize(2);
  const auto c2 = vertex_descendants(two), c7 = vertex_descendants(seven);
  for (Index v = 0; v < L.vertex_count; ++v) {
    const double e2 = dist(at(points[2], c2[v]), at(l, v)), e7 = dist(at(points[7], c7[v]), at(l, v));
    CHECK(e7 < 1e-3);
    CHECK(e7 <= e2 / 20 + 1e-14);
  }
}

template <class T>
bool uses(const LimitChoice& c) {
  return dynamic_cast<const T*>(c.evaluator.get()) != nullptr;
}

}  // namespace

TEST_CASE("Catmull-Clark's analysed masks are Halstead, Kass & DeRose 1993's formula, and the limit of deep refinement") {
  for (const Mesh& mesh : {cross_mesh(), torus(6, 5), pyramid(), cube()}) {
    const Level L = mesh.level();
    const StencilTable t = analysed("catmull-clark", L);
    CHECK(max_row_difference(t, CatmullClarkLimit().limit_stencils(L)) < 1e-12);
    const std::vector<double> got = t.apply(mesh.positions, 3);
    bool quads = true;
    for (Index f = 0; f < L.face_count(); ++f) quads &= L.face_size(f) == 4;
    if (quads)
      for (Index v = 0; v < L.vertex_count; ++v) CHECK(dist(at(got, v), cc_limit_point(L, mesh.positions, v)) < 1e-12);
    check_refinement_approaches("catmull-clark", L, mesh.positions, t);
  }
}

TEST_CASE("Loop's and sqrt(3)'s analysed masks are Loop's gamma_n and Kobbelt's b_n forms") {
  for (const Mesh& mesh : {bipyramid(7), octahedron(), bipyramid(3)}) {
    const Level L = mesh.level();
    const StencilTable t = analysed("loop", L);
    const std::vector<double> got = t.apply(mesh.positions, 3);
    for (Index v = 0; v < L.vertex_count; ++v) CHECK(dist(at(got, v), loop_limit_point(L, mesh.positions, v)) < 1e-12);
    CHECK(max_row_difference(analysed("loop", L, {{"beta", "warren"}}), LoopLimit(LoopBeta::Warren).limit_stencils(L)) <
          1e-12);
    CHECK(max_row_difference(analysed("sqrt3", L), Sqrt3Limit().limit_stencils(L)) < 1e-12);
    check_refinement_approaches("loop", L, mesh.positions, t);
  }
}

TEST_CASE("masks are chosen by l S = l on the mesh, not by name") {
  CHECK(uses<AnalysedLimit>(choose("catmull-clark", grid(3, 2))));
  CHECK(uses<AnalysedLimit>(choose("loop", grid(3, 2, true))));
  CHECK(uses<AnalysedLimit>(choose("quad-bspline", cross_mesh())));
  CHECK(uses<InterpolatoryLimit>(choose("butterfly", octahedron())));
  CHECK(uses<InterpolatoryLimit>(choose("modified-butterfly", octahedron())));
  CHECK(uses<InterpolatoryLimit>(choose("bilinear", cube())));
  // The checker refuses a wrong mask on its own merits: Warren's weights are not Loop's.
  const Level L = octahedron().level();
  CHECK_FALSE(invariance_mismatch(LoopLimit(LoopBeta::Warren), *load_scheme("loop"), L, {}).empty());
  CHECK(invariance_mismatch(LoopLimit(LoopBeta::Loop), *load_scheme("loop"), L, {}).empty());
  CHECK_FALSE(invariance_mismatch(InterpolatoryLimit(), *load_scheme("loop"), L, {}).empty());
}

TEST_CASE("Chen et al. 2008: progressive interpolation on plain Catmull-Clark converges on the cross and the torus") {
  for (const Mesh& mesh : {cross_mesh(), torus(8, 6)}) {
    const Level L = mesh.level();
    const LimitChoice c = choose("catmull-clark", mesh);
    ProgressiveOptions o;
    o.max_iterations = 2000;
    const ProgressiveResult r = progressive_interpolation(*c.evaluator, L, mesh.positions, {}, o);
    REQUIRE(r.converged);
    for (Index v = 0; v < L.vertex_count; ++v)
      CHECK(dist(cc_limit_point(L, r.control, v), at(mesh.positions, v)) < 1e-10 + 1e-14);
    for (size_t k = 1; k < r.history.size(); ++k) CHECK(r.history[k].rms_residual < r.history[k - 1].rms_residual);
    // Local: the fixed vertices never move and theorem 2 holds for this operator too.
    std::vector<std::uint8_t> moving(size_t(L.vertex_count), 0);
    for (Index v = 0; v < L.vertex_count; v += 2) moving[v] = 1;
    const StencilTable limit = c.evaluator->limit_stencils(L);
    const ProgressiveResult local = progressive_interpolation(limit, mesh.positions, moving, o);
    REQUIRE(local.converged);
    const auto predicted = predicted_fixed_offsets(limit, mesh.positions, moving);
    for (Index v = 0; v < L.vertex_count; ++v) {
      if (moving[v]) {
        CHECK(dist(cc_limit_point(L, local.control, v), at(mesh.positions, v)) < 1e-10 + 1e-14);
        continue;
      }
      CHECK(at(local.control, v) == at(mesh.positions, v));
      const P3 offset = at(mesh.positions, v) + (-1.0) * cc_limit_point(L, local.control, v);
      CHECK(dist(offset, at(predicted, v)) < 1e-9);
    }
  }
}

TEST_CASE("the generic method runs on Loop and sqrt(3)") {
  for (const Mesh& mesh : {octahedron(), bipyramid(5)}) {
    const Level L = mesh.level();
    const LimitChoice c = choose("sqrt3", mesh);
    const ProgressiveResult r = progressive_interpolation(*c.evaluator, L, mesh.positions, {});
    REQUIRE(r.converged);
    const StencilTable kobbelt = Sqrt3Limit().limit_stencils(L);
    const std::vector<double> reached = kobbelt.apply(r.control, 3);
    for (Index v = 0; v < L.vertex_count; ++v) CHECK(dist(at(reached, v), at(mesh.positions, v)) < 1e-10);
  }
  const Mesh mesh = bipyramid(6);
  const Level L = mesh.level();
  const ProgressiveResult r = progressive_interpolation(*choose("loop", mesh).evaluator, L, mesh.positions, {});
  REQUIRE(r.converged);
  for (Index v = 0; v < L.vertex_count; ++v)
    CHECK(dist(loop_limit_point(L, r.control, v), at(mesh.positions, v)) < 1e-10 + 1e-14);
}

TEST_CASE("sqrt(3) with boundaries: the check spans two steps, boundary limits are the cubic B-spline's") {
  // Kobbelt 2000: boundary vertices stay in even steps and move in odd ones, so the identity
  // survives the first step on a strip whose every vertex is on the boundary, and only the
  // second step shows it is not sqrt(3)'s limit.
  const Mesh strip = grid(4, 1, true);
  const Level L = strip.level();
  CHECK_FALSE(invariance_mismatch(InterpolatoryLimit(), *load_scheme("sqrt3"), L, {}).empty());
  const LimitChoice c = choose("sqrt3", strip);
  REQUIRE(uses<AnalysedLimit>(c));
  const StencilTable t = c.evaluator->limit_stencils(L);
  // Along the boundary the limit is the uniform cubic B-spline's at its knots, (1, 4, 1)/6,
  // whatever the arity of the curve scheme; corners (one face) stay.
  int checked = 0;
  for (Index v = 0; v < L.vertex_count; ++v) {
    std::vector<Index> along;
    for (Index e : L.ring_edges(v))
      if (L.edge_on_boundary(e)) along.push_back(L.other_end(e, v));
    if (L.ring_faces(v).size() == 1) {
      CHECK(std::abs(weight_of(t, v, v) - 1.0) < 1e-12);
      continue;
    }
    REQUIRE(along.size() == 2);
    CHECK(std::abs(weight_of(t, v, v) - 4.0 / 6) < 1e-12);
    for (Index u : along) CHECK(std::abs(weight_of(t, v, u) - 1.0 / 6) < 1e-12);
    ++checked;
  }
  CHECK(checked > 0);
  check_refinement_approaches("sqrt3", L, strip.positions, t);
  const ProgressiveResult r = progressive_interpolation(*c.evaluator, L, strip.positions, {});
  CHECK(r.converged);
}

TEST_CASE("user schemes get their masks from the analysis; divergent ones are refused") {
  const auto dir = std::filesystem::temp_directory_path() / "subdivkit-interp-user";
  std::filesystem::create_directories(dir);
  // Catmull-Clark's face and edge points with a different vertex rule: no closed form is
  // known to us, the analysis finds the mask, and deep refinement agrees with it.
  const auto variant = dir / "cc-variant.json";
  std::ofstream(variant) << R"json({"name": "cc-variant", "split": "quad", "faces": "any", "curve": "cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
              "vertex": [{"at": "self", "w": "1/2"}, {"sum": "ring", "w": "1/(2*n)"}]}})json";
  const Mesh cross = cross_mesh();
  const LimitChoice c = choose(variant.string(), cross);
  CHECK(uses<AnalysedLimit>(c));
  const StencilTable t = c.evaluator->limit_stencils(cross.level());
  check_refinement_approaches(variant.string(), cross.level(), cross.positions, t);
  const ProgressiveResult r = progressive_interpolation(t, cross.positions, {}, {});
  REQUIRE(r.converged);
  const std::vector<double> reached = t.apply(r.control, 3);
  for (Index v = 0; v < cross.level().vertex_count; ++v) CHECK(dist(at(reached, v), at(cross.positions, v)) < 1e-10);

  // v' = 2 v - mean(ring) over bilinear edge points: v - mean(e) grows by 3/2 per step, so
  // 1 is not the dominant eigenvalue and no limit exists.
  const auto divergent = dir / "divergent.json";
  std::ofstream(divergent) << R"json({"name": "divergent", "split": "quad", "faces": "any", "curve": "cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": "1/2"}],
              "vertex": [{"at": "self", "w": "2"}, {"sum": "ring", "w": "-1/n"}]}})json";
  CHECK_THROWS_WITH_AS(choose(divergent.string(), cube()), doctest::Contains("has no limit mask"), Error);
  const std::string analyze_hint = "`subdiv analyze " + divergent.string() + "`";  // the file, as analyze takes it
  CHECK_THROWS_WITH_AS(choose(divergent.string(), cube()), doctest::Contains(analyze_hint.c_str()), Error);
  // A provider (a plugin's hook) is consulted after the analysis and checked like it.
  // The registry outlives this test case, so the provider owns its counter.
  auto asked = std::make_shared<int>(0);
  register_limit_mask_provider("test provider", [asked](const Scheme& s, const FeatureOptions&) {
    ++*asked;
    return s.name == "divergent" ? std::make_shared<CatmullClarkLimit>() : nullptr;
  });
  CHECK_THROWS_WITH_AS(choose(divergent.string(), cube()), doctest::Contains("Registered providers (test provider)"),
                       Error);
  CHECK(*asked > 0);
}

TEST_CASE("a scheme without boundary rules: its masks on a closed mesh are the shipped scheme's") {
  // Catmull-Clark's rules without a "curve" refine a closed mesh without creases exactly as
  // the shipped scheme does, so their limit masks must be the same; the analysis' cut
  // neighbourhoods take stand-in rim rules (analysis/surface/rim_rules.h) that never reach a
  // mask. On a mesh with a boundary the scheme's own rules are missing, and that is said.
  const auto dir = std::filesystem::temp_directory_path() / "subdivkit-interp-no-curve";
  std::filesystem::create_directories(dir);
  const auto bare = dir / "cc-no-curve.json";
  std::ofstream(bare) << R"json({"name": "cc-no-curve", "split": "quad",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
              "vertex": [{"at": "self", "w": "(n-2)/n"}, {"sum": "ring", "w": "1/n^2"},
                         {"sum": "faces", "new": "face", "w": "1/n^2"}]}})json";
  for (const Mesh& m : {cube(), torus(5, 4)}) {
    const StencilTable ours = analysed(bare.string(), m.level()), shipped = analysed("catmull-clark", m.level());
    CHECK(max_row_difference(ours, shipped) < 1e-13);
  }
  CHECK_THROWS_WITH_AS(choose(bare.string(), grid(3, 2)), doctest::Contains("\"curve\""), Error);
}

TEST_CASE("refusals: missing vertices in a selection") {
  CHECK_THROWS_WITH_AS(parse_vertex_selection("0,1,40", 40, "--select"), doctest::Contains("vertex 40 does not exist"), Error);
  CHECK_THROWS_WITH_AS(parse_vertex_selection("0,-1", 40, "--select"), doctest::Contains("does not exist"), Error);
  CHECK_THROWS_WITH_AS(parse_vertex_selection("0,x", 40, "--select"), doctest::Contains("'x' is not a vertex id"), Error);
  CHECK_THROWS_WITH_AS(parse_vertex_selection("# none\n", 40, "ids.txt"), doctest::Contains("names no vertices"), Error);
  CHECK_THROWS_WITH_AS(parse_vertex_selection("1\n2\n99\n", 40, "ids.txt"), doctest::Contains("ids.txt line 3"), Error);
  const auto s = parse_vertex_selection("3, 1 # a comment 7\n3\n", 5, "ids.txt");
  CHECK(s == std::vector<std::uint8_t>{0, 1, 0, 1, 0});
  CHECK(parse_vertex_selection("all", 3, "--select") == std::vector<std::uint8_t>{1, 1, 1});
}

TEST_CASE("darts and semi-sharp creases: exact masks through refinement, and interpolation converges") {
  const Mesh mesh = torus(6, 5);
  for (float sharpness : {10.f, 2.f, 1.5f}) {
    Level L = mesh.level();
    L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
    L.edge_sharpness[0] = sharpness;  // one sharp edge: two darts, or a fading crease
    const StencilTable t = analysed("catmull-clark", L);  // l S = l checked on this mesh
    check_refinement_approaches("catmull-clark", L, mesh.positions, t);
    const ProgressiveResult r = progressive_interpolation(t, mesh.positions, {}, {});
    REQUIRE(r.converged);
    const std::vector<double> reached = t.apply(r.control, 3);
    for (Index v = 0; v < L.vertex_count; ++v) CHECK(dist(at(reached, v), at(mesh.positions, v)) < 1e-10);
  }
}

TEST_CASE("creases and corners: cubic B-spline limits along infinitely sharp edges, corners stay") {
  // The bundled creased cube, through l S = l: the closed form must pass on it.
  const MeshData d = read_mesh(std::string(SUBDIV_SOURCE_DIR) + "/examples/meshes/cube-creased.obj");
  Mesh m;
  m.vertex_count = d.vertex_count(), m.offsets.assign(d.face_offsets.begin(), d.face_offsets.end()), m.corners.assign(d.face_vertices.begin(), d.face_vertices.end()), m.positions = d.positions;
  Level L = m.level();
  for (const auto& c : d.creases) {
    if (L.edge_sharpness.empty()) L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
    L.edge_sharpness[find_edge(L, c.v0, c.v1)] = float(c.sharpness);
  }
  for (const auto& c : d.corners) {
    if (L.vertex_sharpness.empty()) L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
    L.vertex_sharpness[c.v] = float(c.sharpness);
  }
  // The hand-written closed form (crease vertices (1/6, 2/3, 1/6), corners fixed) passes
  // l S = l, and the analysed masks are it.
  CHECK(invariance_mismatch(CatmullClarkLimit(), *load_scheme("catmull-clark"), L, {}).empty());
  const StencilTable t = analysed("catmull-clark", L);
  CHECK(max_row_difference(t, CatmullClarkLimit().limit_stencils(L)) < 1e-12);
  for (const auto& c : d.corners) {
    CHECK(t.row_size(c.v) == 1);
    CHECK(std::abs(weight_of(t, c.v, c.v) - 1.0) < 1e-12);
  }
}

namespace {

// Doo & Sabin 1978: Doo-Sabin's corner point of corner c in a k-gon, gamma_0 = (k+5)/(4k),
// gamma_i = (3 + 2 cos(2 pi i/k))/(4k), i counted from the corner.
P3 doo_sabin_corner(const Level& L, const std::vector<double>& x, Index f, int c) {
  const auto face = L.face(f);
  const int k = int(face.size());
  P3 p{};
  for (int i = 0; i < k; ++i) {
    const double g = i == 0 ? (k + 5.0) / (4.0 * k) : (3 + 2 * std::cos(2 * std::numbers::pi * i / k)) / (4.0 * k);
    p = p + g * at(x, face[(c + i) % k]);
  }
  return p;
}

// The centroid of v's V-face: the mean of its corner points over the faces around v.
P3 doo_sabin_vface_centroid(const Level& L, const std::vector<double>& x, Index v) {
  const auto faces = L.ring_faces(v);
  P3 s{};
  for (size_t i = 0; i < faces.size(); ++i) {
    const int c = L.vertex_face_corner[L.vertex_face_offsets[v] + i];
    s = s + (1.0 / faces.size()) * doo_sabin_corner(L, x, faces[i], c);
  }
  return s;
}

}  // namespace

TEST_CASE("dual schemes: a control vertex's limit point is its V-face's centroid (Doo & Sabin 1978)") {
  for (const Mesh& mesh : {cross_mesh(), pyramid()}) {
    const Level L = mesh.level();
    const LimitChoice c = choose("doo-sabin", mesh);
    CHECK(uses<DualCentroidLimit>(c));
    std::vector<double> got(mesh.positions.size());
    c.evaluator->limit_points(L, mesh.positions, got);
    for (Index v = 0; v < L.vertex_count; ++v)
      CHECK(dist(at(got, v), doo_sabin_vface_centroid(L, mesh.positions, v)) < 1e-14);
    // Mid-edge: the V-face is the midpoints of v's edges.
    choose("mid-edge", mesh).evaluator->limit_points(L, mesh.positions, got);
    for (Index v = 0; v < L.vertex_count; ++v) {
      P3 m{};
      for (Index e : L.ring_edges(v)) m = m + (0.5 / L.valence(v)) * (at(mesh.positions, v) + at(mesh.positions, L.other_end(e, v)));
      CHECK(dist(at(got, v), m) < 1e-14);
    }
  }
  // The nested faces inside a V-face keep its centroid and shrink onto it: the limit point.
  const Mesh mesh = pyramid();
  const Level L = mesh.level();
  const auto r = refine_mesh(mesh, "doo-sabin", 6);
  std::vector<double> limit(mesh.positions.size());
  choose("doo-sabin", mesh).evaluator->limit_points(L, mesh.positions, limit);
  const std::vector<Index> vface = vertex_faces_after_step(r.hierarchy);
  for (Index v = 0; v < L.vertex_count; ++v) {
    Index g = vface[v];
    std::vector<double> x = r.hierarchy.stencils[0].apply(mesh.positions, 3);
    double radius = 0;
    for (int l = 1; l <= 6; ++l) {
      const auto face = r.hierarchy.levels[l].face(g);
      P3 centre{};
      radius = 0;
      for (Index u : face) centre = centre + (1.0 / face.size()) * at(x, u);
      for (Index u : face) radius = std::max(radius, dist(at(x, u), at(limit, v)));
      CHECK(dist(centre, at(limit, v)) < 1e-13);
      if (l == 6) break;
      const auto& parents = r.hierarchy.origins[l].parent_face;
      g = Index(std::find(parents.begin(), parents.end(), g) - parents.begin());
      x = r.hierarchy.stencils[l].apply(x, 3);
    }
    CHECK(radius < 0.02);
  }
  // Interpolation with Doo-Sabin converges to the V-face centroids.
  const Mesh cross = cross_mesh();
  const Level C = cross.level();
  const ProgressiveResult p = progressive_interpolation(*choose("doo-sabin", cross).evaluator, C, cross.positions, {});
  REQUIRE(p.converged);
  for (Index v = 0; v < C.vertex_count; ++v)
    CHECK(dist(doo_sabin_vface_centroid(C, p.control, v), at(cross.positions, v)) < 1e-10 + 1e-14);
  // A boundary vertex's V-face is open; its limit is on the boundary's Chaikin curve, the
  // quadratic B-spline's (p + 6 v + q) / 8 (a boundary vertex with one face is a corner).
  const Mesh g = grid(2, 2);
  const LimitChoice b = choose("doo-sabin", g);
  std::vector<double> got(g.positions.size());
  b.evaluator->limit_points(g.level(), g.positions, got);
  CHECK(dist(at(got, 0), at(g.positions, 0)) == 0.0);
  for (int c = 0; c < 3; ++c)
    CHECK(got[size_t(3 + c)] == doctest::Approx((g.positions[size_t(c)] + 6 * g.positions[size_t(3 + c)] + g.positions[size_t(6 + c)]) / 8));
}
