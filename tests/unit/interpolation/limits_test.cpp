// The generic method: closed-form limit masks, their selection by l S = l, Chen et al.'s
// progressive interpolation on plain Catmull-Clark, Loop, dual schemes, and the refusals.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "framework/interpolation/closed_form_limits.h"
#include "framework/interpolation/dual_limits.h"
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

// Seed 000 §5's Loop limit: gamma_n v + (1 - gamma_n) mean(e), gamma_n = 3 / (11 - 8 beta_bar_n),
// beta_bar_n = 3/8 + (3/8 + cos(2 pi/n)/4)^2.
P3 loop_limit_point(const Level& L, const std::vector<double>& x, Index v) {
  const int n = L.valence(v);
  const double c = 3.0 / 8 + std::cos(2 * std::numbers::pi / n) / 4, beta_bar = 3.0 / 8 + c * c;
  const double gamma = 3.0 / (11 - 8 * beta_bar);
  P3 s = gamma * at(x, v);
  for (Index e : L.ring_edges(v)) s = s + ((1 - gamma) / n) * at(x, L.other_end(e, v));
  return s;
}

LimitChoice choose(const std::string& scheme, const Mesh& m, const ParameterOverrides& p = {}) {
  return select_limit(load_scheme_sequence(scheme, 1, p), m.level());
}

template <class T>
bool uses(const LimitChoice& c) {
  return dynamic_cast<const T*>(c.evaluator.get()) != nullptr;
}

}  // namespace

TEST_CASE("the Catmull-Clark mask is seed 000's formula on quads, and the limit of deep refinement") {
  for (const Mesh& mesh : {cross_mesh(), torus(6, 5)}) {
    const Level L = mesh.level();
    std::vector<double> got(mesh.positions.size());
    CatmullClarkLimit().limit_points(L, mesh.positions, got);
    for (Index v = 0; v < L.vertex_count; ++v) CHECK(dist(at(got, v), cc_limit_point(L, mesh.positions, v)) < 1e-14);
    // Vertex points of 2 and 6 levels: their distance to the limit falls geometrically.
    const auto r2 = refine_mesh(mesh, "catmull-clark", 2), r6 = refine_mesh(mesh, "catmull-clark", 6);
    const auto c2 = vertex_descendants(r2.hierarchy), c6 = vertex_descendants(r6.hierarchy);
    for (Index v = 0; v < L.vertex_count; ++v) {
      const double e2 = dist(at(r2.positions, c2[v]), at(got, v)), e6 = dist(at(r6.positions, c6[v]), at(got, v));
      CHECK(e6 < 1e-3);
      CHECK(e6 < e2 / 50);  // valence 3 converges slowest: about 1/3 per level
    }
  }
}

TEST_CASE("the Loop mask is seed 000's gamma_n form") {
  const Mesh mesh = bipyramid(7);
  const Level L = mesh.level();
  std::vector<double> got(mesh.positions.size());
  LoopLimit().limit_points(L, mesh.positions, got);
  for (Index v = 0; v < L.vertex_count; ++v) CHECK(dist(at(got, v), loop_limit_point(L, mesh.positions, v)) < 1e-14);
}

TEST_CASE("masks are chosen by l S = l on the mesh, not by name") {
  CHECK(uses<CatmullClarkLimit>(choose("catmull-clark", cross_mesh())));
  CHECK(uses<CatmullClarkLimit>(choose("catmull-clark", pyramid())));
  CHECK(uses<CatmullClarkLimit>(choose("catmull-clark", grid(3, 2))));
  auto loop_beta_of = [](const LimitChoice& c) { return dynamic_cast<const LoopLimit&>(*c.evaluator).beta(); };
  CHECK(loop_beta_of(choose("loop", bipyramid(5))) == LoopBeta::Loop);
  CHECK(loop_beta_of(choose("loop", bipyramid(5), {{"beta", "warren"}})) == LoopBeta::Warren);
  CHECK(loop_beta_of(choose("loop", grid(3, 2, true))) == LoopBeta::Loop);
  CHECK(uses<Sqrt3Limit>(choose("sqrt3", octahedron())));
  CHECK(uses<InterpolatoryLimit>(choose("butterfly", octahedron())));
  CHECK(uses<InterpolatoryLimit>(choose("bilinear", cube())));
  // Every candidate's mask passes or fails the test on its own merits.
  const Level L = octahedron().level();
  CHECK_FALSE(invariance_mismatch(LoopLimit(LoopBeta::Warren), *load_scheme("loop"), L, {}).empty());
  CHECK(invariance_mismatch(LoopLimit(LoopBeta::Loop), *load_scheme("loop"), L, {}).empty());
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

TEST_CASE("the generic method runs on Loop") {
  const Mesh mesh = bipyramid(6);
  const Level L = mesh.level();
  const ProgressiveResult r = progressive_interpolation(*choose("loop", mesh).evaluator, L, mesh.positions, {});
  REQUIRE(r.converged);
  for (Index v = 0; v < L.vertex_count; ++v)
    CHECK(dist(loop_limit_point(L, r.control, v), at(mesh.positions, v)) < 1e-10 + 1e-14);
}

TEST_CASE("refusals: schemes without limit masks, dual schemes, missing vertices") {
  // A user scheme: Catmull-Clark with a different vertex rule has no closed-form mask.
  const auto dir = std::filesystem::temp_directory_path() / "subdivkit-interp-user";
  std::filesystem::create_directories(dir);
  const auto json = dir / "cc-variant.json";
  std::ofstream(json) << R"json({"name": "cc-variant", "split": "quad", "faces": "any", "curve": "cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
              "vertex": [{"at": "self", "w": "1/2"}, {"sum": "ring", "w": "1/(2*n)"}]}})json";
  CHECK_THROWS_WITH_AS(choose(json.string(), cube()), doctest::Contains("has no limit mask"), Error);
  CHECK_THROWS_WITH_AS(choose(json.string(), cube()), doctest::Contains("issue 6"), Error);
  // A provider (issue 6's hook) is consulted and checked like the closed forms.
  int asked = 0;
  register_limit_mask_provider("test provider", [&](const Scheme& s, const FeatureOptions&) {
    ++asked;
    return s.name == "cc-variant" ? std::make_shared<CatmullClarkLimit>() : nullptr;
  });
  CHECK_THROWS_WITH_AS(choose(json.string(), cube()), doctest::Contains("Registered providers (test provider)"), Error);
  CHECK(asked > 0);
  // Selections.
  CHECK_THROWS_WITH_AS(parse_vertex_selection("0,1,40", 40, "--select"), doctest::Contains("vertex 40 does not exist"), Error);
  CHECK_THROWS_WITH_AS(parse_vertex_selection("0,-1", 40, "--select"), doctest::Contains("does not exist"), Error);
  CHECK_THROWS_WITH_AS(parse_vertex_selection("0,x", 40, "--select"), doctest::Contains("'x' is not a vertex id"), Error);
  CHECK_THROWS_WITH_AS(parse_vertex_selection("# none\n", 40, "ids.txt"), doctest::Contains("names no vertices"), Error);
  CHECK_THROWS_WITH_AS(parse_vertex_selection("1\n2\n99\n", 40, "ids.txt"), doctest::Contains("ids.txt line 3"), Error);
  const auto s = parse_vertex_selection("3, 1 # a comment 7\n3\n", 5, "ids.txt");
  CHECK(s == std::vector<std::uint8_t>{0, 1, 0, 1, 0});
  CHECK(parse_vertex_selection("all", 3, "--select") == std::vector<std::uint8_t>{1, 1, 1});
  // A dart has no closed-form mask; the vertex is named.
  Level dart = torus(4, 4).level();
  dart.edge_sharpness.assign(size_t(dart.edge_count()), 0.f);
  dart.edge_sharpness[0] = 10.f;
  CHECK_THROWS_WITH_AS(CatmullClarkLimit().limit_stencils(dart), doctest::Contains("is a dart"), Error);
  dart.edge_sharpness[0] = 2.f;
  CHECK_THROWS_WITH_AS(CatmullClarkLimit().limit_stencils(dart), doctest::Contains("semi-sharp"), Error);
}

TEST_CASE("creases and corners: cubic B-spline limits along infinitely sharp edges, corners stay") {
  // The bundled creased cube, through l S = l: the closed form must pass on it.
  const MeshData d = read_mesh(std::string(SUBDIV_SOURCE_DIR) + "/examples/meshes/cube-creased.obj");
  Mesh m;
  m.vertex_count = d.vertex_count(), m.offsets = d.face_offsets, m.corners = d.face_vertices, m.positions = d.positions;
  Level L = m.level();
  for (const auto& c : d.creases) {
    if (L.edge_sharpness.empty()) L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
    L.edge_sharpness[find_edge(L, c.v0, c.v1)] = float(c.sharpness);
  }
  for (const auto& c : d.corners) {
    if (L.vertex_sharpness.empty()) L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
    L.vertex_sharpness[c.v] = float(c.sharpness);
  }
  CHECK(invariance_mismatch(CatmullClarkLimit(), *load_scheme("catmull-clark"), L, {}).empty());
  const StencilTable t = CatmullClarkLimit().limit_stencils(L);
  for (const auto& c : d.corners) {
    CHECK(t.row_size(c.v) == 1);
    CHECK(weight_of(t, c.v, c.v) == 1.0);
  }
}

namespace {

// Seed 000 §4(b): Doo-Sabin's corner point of corner c in a k-gon, gamma_0 = (k+5)/(4k),
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

TEST_CASE("dual schemes: a control vertex's limit point is its V-face's centroid (seed 000 §5)") {
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
  // A boundary vertex's V-face is open: refused with the vertex named.
  CHECK_THROWS_WITH_AS(choose("doo-sabin", grid(2, 2)), doctest::Contains("vertex 0 is on the boundary"), Error);
}
