// Crease ends of even-degree quad B-splines (docs/features.md, "Creases in dual schemes",
// "Corners"): along a crease polygon c, M1, M2, ... between two corners, the crease points of
// `quad-bspline -p d=4` and `d=6` are at every level the control polygon of the clamped
// uniform degree-d B-spline whose derivatives 2 .. d/2 vanish at the corners, refined by
// inserting every interval's midpoint (Boehm 1980, "Inserting new knots into B-spline
// curves"), computed here independently of the engine; the corners stay; crease rules
// chosen by distance from a corner load, validate and are refused where malformed.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <tbb/global_control.h>

#include "framework/scheme/scheme_validator.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;

namespace {

using P3 = std::array<double, 3>;
using Polygon = std::vector<P3>;

P3 mix(double a, const P3& p, double b, const P3& q) { return {a * p[0] + b * q[0], a * p[1] + b * q[1], a * p[2] + b * q[2]}; }
double dist(const P3& a, const P3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// Boehm 1980: insert knot t once into a B-spline of degree p; for t_k <= t < t_{k+1},
// Q_i = (1 - a_i) P_{i-1} + a_i P_i with a_i = (t - t_i) / (t_{i+p} - t_i), k-p+1 <= i <= k.
void insert_knot(std::vector<double>& knots, Polygon& ctrl, int p, double t) {
  size_t k = 0;
  while (!(knots[k] <= t && t < knots[k + 1])) ++k;
  Polygon q;
  for (size_t i = 0; i <= ctrl.size(); ++i) {
    if (i + size_t(p) <= k) q.push_back(ctrl[i]);
    else if (i > k) q.push_back(ctrl[i - 1]);
    else {
      const double a = (t - knots[i]) / (knots[i + size_t(p)] - knots[i]);
      q.push_back(mix(1 - a, ctrl[i - 1], a, ctrl[i]));
    }
  }
  knots.insert(knots.begin() + ptrdiff_t(k) + 1, t);
  ctrl = q;
}

// With clamped uniform knots 0 (d + 1 times), 1, 2, ..., a curve whose derivatives 2 .. m
// (m = d/2) vanish at 0 has control points Q_i = c + i(i + 1)/(m(m + 1)) (Q_m - c) for
// i <= m: the blossom of its first piece c + t v + O(t^(m+1)) at (0, ..., 0, 1, ..., i).
P3 implied(const P3& c, const P3& q, int i, int m) {
  const double s = double(i * (i + 1)) / double(m * (m + 1));
  return mix(1 - s, c, s, q);
}

// The crease polygon's curve: the clamped degree-d B-spline of c, [implied points], M1, ...,
// M_{N-1}, [implied points], c'. `levels` times every knot interval's midpoint is inserted;
// returns the control polygon without the implied points, after checking that they are where
// the end condition puts them (it holds on every level: a property of the curve).
Polygon natural_clamped_refined(const Polygon& p, int d, int levels) {
  const int m = d / 2;
  Polygon ctrl{p.front()};
  for (int i = 1; i < m; ++i) ctrl.push_back(implied(p.front(), p[1], i, m));
  ctrl.insert(ctrl.end(), p.begin() + 1, p.end() - 1);
  for (int i = m - 1; i >= 1; --i) ctrl.push_back(implied(p.back(), p[p.size() - 2], i, m));
  ctrl.push_back(p.back());
  const int intervals = int(ctrl.size()) - d;
  std::vector<double> knots(size_t(d + 1), 0.0);
  for (int i = 1; i < intervals; ++i) knots.push_back(i);
  knots.insert(knots.end(), size_t(d + 1), double(intervals));
  for (int l = 0; l < levels; ++l) {
    std::vector<double> mids;
    for (size_t i = 0; i + 1 < knots.size(); ++i)
      if (knots[i] < knots[i + 1]) mids.push_back(0.5 * (knots[i] + knots[i + 1]));
    for (double t : mids) insert_knot(knots, ctrl, d, t);
  }
  const size_t n = ctrl.size();
  for (int i = 1; i < m; ++i) {
    CHECK(dist(ctrl[size_t(i)], implied(ctrl[0], ctrl[size_t(m)], i, m)) < 1e-13);
    CHECK(dist(ctrl[n - 1 - size_t(i)], implied(ctrl[n - 1], ctrl[n - 1 - size_t(m)], i, m)) < 1e-13);
  }
  Polygon out{ctrl.front()};
  out.insert(out.end(), ctrl.begin() + m, ctrl.end() - m);
  out.push_back(ctrl.back());
  return out;
}

// A 12 x 6 grid, bent, with a crease along grid edges from boundary vertex (0, 2) to (12, 3)
// that turns six times (crease valences 3 and 4 on both sides); its ends have three sharp
// edges (two boundary ones), so they are corners. 14 crease points: long enough for d = 6.
struct CreasedGrid {
  test::Mesh mesh;
  std::vector<Index> path;
};

CreasedGrid creased_grid() {
  test::Mesh m = test::grid(12, 6);
  for (Index v = 0; v < m.vertex_count; ++v) {
    const double x = m.positions[3 * v], y = m.positions[3 * v + 1];
    m.positions[3 * v + 2] = 0.3 * std::sin(0.6 * x) * std::cos(0.7 * y) + 0.03 * x * y;
    m.positions[3 * v] += 0.1 * std::sin(2.1 * v);
    m.positions[3 * v + 1] += 0.08 * std::cos(1.3 * v);
  }
  auto id = [](int i, int j) { return Index(j * 13 + i); };
  return {m, {id(0, 2), id(1, 2), id(2, 2), id(2, 3), id(3, 3), id(4, 3), id(5, 3), id(5, 2), id(6, 2), id(7, 2),
              id(8, 2), id(8, 3), id(9, 3), id(10, 3), id(11, 3), id(12, 3)}};
}

Level tagged(const test::Mesh& m, const std::vector<Index>& path) {
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Index e = find_edge(L, path[i], path[i + 1]);
    REQUIRE(e != kNone);
    L.edge_sharpness[e] = 10.f;
  }
  return L;
}

// The interior sharp edges of L chained from `start`.
std::vector<Index> crease_chain(const Level& L, Index start) {
  std::vector<std::vector<Index>> next(size_t(L.vertex_count));
  for (Index e = 0; e < L.edge_count(); ++e)
    if (!L.edge_on_boundary(e) && L.edge_sharp(e) > 0.f) {
      next[size_t(L.edge_vertices[2 * e])].push_back(L.edge_vertices[2 * e + 1]);
      next[size_t(L.edge_vertices[2 * e + 1])].push_back(L.edge_vertices[2 * e]);
    }
  std::vector<Index> chain{start};
  Index prev = kNone, v = start;
  while (chain.size() <= size_t(L.vertex_count)) {
    Index to = kNone;
    for (Index w : next[size_t(v)])
      if (w != prev) to = w;
    if (to == kNone) break;
    chain.push_back(to);
    prev = v, v = to;
  }
  return chain;
}

P3 point(const std::vector<double>& pos, Index v) { return {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]}; }

// The crease of level l of h, from the child vertex on the first corner.
Polygon crease_at(const Hierarchy& h, int l, const std::vector<double>& base_positions, const P3& first) {
  const Level& L = h.levels[size_t(l)];
  const auto pos = interpolate(h, l, base_positions, 3);
  Index start = kNone;
  for (Index v = 0; v < L.vertex_count; ++v)
    if (dist(point(pos, v), first) == 0.0) start = v;
  REQUIRE(start != kNone);
  Polygon got;
  for (Index v : crease_chain(L, start)) got.push_back(point(pos, v));
  return got;
}

std::string write(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "subdivkit-crease-ends";
  std::filesystem::create_directories(dir);
  const auto file = dir / (name + ".json");
  std::ofstream(file) << text;
  return file.string();
}

// A quad-split scheme whose one smoothing pass has this vertex rule.
std::string pass_with(const std::string& vertex) {
  return "{\"name\": \"p\", \"faces\": \"any\", \"steps\": [\n"
         "  {\"split\": \"quad\", \"rules\": {\"face\": [{\"sum\": \"vertices\", \"w\": \"1/k\"}], "
         "\"edge\": [{\"sum\": \"ends\", \"w\": \"1/2\"}], \"vertex\": [{\"at\": \"self\", \"w\": \"1\"}]}},\n"
         "  {\"smooth\": {\"vertex\": " + vertex + "}}]}\n";
}

std::string load_error(const std::string& text) {
  try {
    load_scheme_text(text, "ends.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("quad-bspline crease ends: a crease between corners is the clamped degree-d B-spline with vanishing "
          "derivatives 2..d/2 at the corners, levels 1-3, corners fixed") {
  const CreasedGrid g = creased_grid();
  Polygon crease;
  for (Index v : g.path) crease.push_back(point(g.mesh.positions, v));
  for (int d : {2, 4, 6}) {
    CAPTURE(d);
    const auto s = load_scheme("quad-bspline", {{"d", std::to_string(d)}});
    RefineOptions options;
    options.levels = 3;
    const Hierarchy h = refine(*s, tagged(g.mesh, g.path), options);
    for (int l = 1; l <= 3; ++l) {
      CAPTURE(l);
      const Polygon expected = natural_clamped_refined(crease, d, l);
      const Polygon got = crease_at(h, l, g.mesh.positions, crease.front());
      REQUIRE(got.size() == expected.size());  // 2N - 2 points from N: one at each corner, two per crease vertex
      double worst = 0;
      for (size_t i = 0; i < got.size(); ++i) worst = std::max(worst, dist(got[i], expected[i]));
      CHECK(worst < 1e-12);
      CHECK(dist(got.back(), crease.back()) == 0.0);  // both corners stay exactly
    }
  }
}

TEST_CASE("quad-bspline crease ends: without the end rules the crease next to a corner is not the clamped spline") {
  // The same scheme with the uniform (1/4, 1/2, 1/4) everywhere, as before the end rules: the
  // test above could fail.
  const CreasedGrid g = creased_grid();
  Polygon crease;
  for (Index v : g.path) crease.push_back(point(g.mesh.positions, v));
  const std::string text = R"json({"name": "uniform-ends", "faces": "any", "steps": [
    {"split": "dual", "curve": "chaikin", "rules": {
      "corner": [{"sum": "vertices", "w": "(j == 0 ? 1/2 : ((j == 1 || j == k - 1) ? 1/8 : 0)) + 1/(4*k)"}]}},
    {"smooth": {"vertex": {"smooth": [{"sum": "face-centroids", "w": "1/n"}],
      "crease": [{"at": "self", "w": "1/2"}, {"sum": "crease-neighbours", "w": "1/4"}]}}}]})json";
  const auto s = load_scheme_text(text, "uniform-ends.json");
  RefineOptions options;
  options.levels = 1;
  const Hierarchy h = refine(*s, tagged(g.mesh, g.path), options);
  const Polygon expected = natural_clamped_refined(crease, 4, 1);
  const Polygon got = crease_at(h, 1, g.mesh.positions, crease.front());
  REQUIRE(got.size() == expected.size());
  CHECK(dist(got[1], expected[1]) > 1e-3);
  CHECK(dist(got[got.size() / 2], expected[got.size() / 2]) < 1e-12);  // the middle is the uniform rule
}

TEST_CASE("quad-bspline crease ends: one and two threads give the same bits") {
  const CreasedGrid g = creased_grid();
  const auto s = load_scheme("quad-bspline", {{"d", "6"}});
  RefineOptions options;
  options.levels = 3;
  std::vector<double> values[2];
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    const Hierarchy h = refine(*s, tagged(g.mesh, g.path), options);
    values[threads - 1] = interpolate(h, 3, g.mesh.positions, 3);
  }
  CHECK(values[0] == values[1]);
}

TEST_CASE("crease-ends: a rule by distance from the nearest corner, reaching crease points two steps away") {
  // Cubic B-spline crease rule everywhere; at distance 2 a rule that reads the corner
  // (step -2) and the point two steps on (step 2): the crease vertex two edges from a corner
  // moves to (corner + point two on)/2 exactly.
  const std::string text = pass_with(R"json({"smooth": [{"at": "self", "w": "1"}],
      "crease": [{"at": "self", "w": "1/2"}, {"sum": "crease-neighbours", "w": "1/4"}],
      "crease-ends": [{"distance": 2, "rule": [{"at": "crease-point", "step": -2, "w": "1/2"},
                                                {"at": "crease-point", "step": 2, "w": "1/2"}]}]})json");
  const auto s = load_scheme_text(text, "two-steps.json");
  const CreasedGrid g = creased_grid();
  RefineOptions options;
  options.levels = 1;
  const Hierarchy h = refine(*s, tagged(g.mesh, g.path), options);
  Polygon crease;
  for (Index v : g.path) crease.push_back(point(g.mesh.positions, v));
  const Polygon got = crease_at(h, 1, g.mesh.positions, crease.front());
  // The quad split puts crease points at the crease vertices and the edge midpoints: child
  // point 2 (distance 2) is M1, its points two steps away the corner and M2.
  REQUIRE(got.size() == 2 * crease.size() - 1);
  CHECK(dist(got[2], mix(0.5, crease[0], 0.5, crease[2])) < 1e-14);
  CHECK(dist(got[got.size() - 3], mix(0.5, crease.back(), 0.5, crease[crease.size() - 3])) < 1e-14);
  const P3 cubic = mix(1, mix(0.125, crease[1], 0.75, crease[2]), 0.125, crease[3]);  // (1/8, 3/4, 1/8), away from corners
  CHECK(dist(got[4], cubic) < 1e-14);
  CHECK(dist(got[0], crease[0]) == 0.0);
}

TEST_CASE("crease-ends: malformed rules are refused with the file and the place") {
  auto with_ends = [](const std::string& ends) {
    return pass_with("{\"smooth\": [{\"at\": \"self\", \"w\": \"1\"}], \"crease-ends\": " + ends + "}");
  };
  const std::string zero = load_error(with_ends(R"([{"distance": 0, "rule": [{"at": "self", "w": "1"}]}])"));
  CHECK(zero.rfind("ends.json:3: steps[1].smooth.vertex.crease-ends[0].distance: 0 is outside [1, 16]", 0) == 0);
  CHECK(load_error(with_ends(R"([{"distance": 1, "rule": [{"at": "self", "w": "1"}]},
                                 {"distance": 1, "rule": [{"at": "self", "w": "1"}]}])"))
            .find("crease-ends[1].distance: distance 1 has a rule already") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 2, "rule": [{"at": "crease-point", "step": -3, "w": "1"}]}])"))
            .find("crease-ends[0].rule[0].step: step -3 reaches past the corner") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 2, "rule": [{"at": "crease-point", "w": "1"}]}])"))
            .find("crease-ends[0].rule[0]: missing \"step\"") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 2, "rule": [{"sum": "crease-point", "step": 1, "w": "1"}]}])"))
            .find("role 'crease-point' is one point: write \"at\": \"crease-point\"") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 2, "rule": [{"at": "self", "step": 1, "w": "1"}]}])"))
            .find("rule[0].step: \"step\" belongs to role 'crease-point'") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 2.5, "rule": [{"at": "self", "w": "1"}]}])"))
            .find("crease-ends[0].distance: must be a whole number") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 2, "rules": []}])")).find("unknown key \"rules\"") != std::string::npos);
  CHECK(load_error(with_ends("{}")).find("crease-ends: expected a non-empty array") != std::string::npos);
  CHECK(load_error(pass_with(R"({"smooth": [{"at": "crease-point", "step": 1, "w": "1"}]})"))
            .find("role 'crease-point' exists only in crease rules") != std::string::npos);
}

TEST_CASE("subdiv validate: crease-end rules are checked for affine weights, with their line and distance") {
  const std::string good = pass_with(R"json({"smooth": [{"at": "self", "w": "1"}],
      "crease-ends": [{"distance": 1, "rule": [{"at": "crease-point", "step": -1, "w": "1/4"}, {"at": "self", "w": "3/4"}]}]})json");
  const auto ok = validate_scheme_file(write("ends-good", good));
  CHECK_MESSAGE(ok.ok(), (ok.errors.empty() ? std::string() : ok.errors[0].message));
  const std::string bad = pass_with(R"json({"smooth": [{"at": "self", "w": "1"}],
      "crease-ends": [{"distance": 1, "rule": [{"at": "crease-point", "step": -1, "w": "1/4"}, {"at": "self", "w": "1/2"}]}]})json");
  const auto r = validate_scheme_file(write("ends-bad", bad));
  REQUIRE_FALSE(r.ok());
  CHECK(r.errors[0].message.find("ends-bad.json:4: steps[1].smooth.vertex.crease-ends[0].rule (crease, distance 1): "
                                 "weights sum to 0.75 at n=3") != std::string::npos);
}
