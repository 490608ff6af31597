// Crease ends of even-degree quad B-splines (docs/features.md, "Creases in dual schemes",
// "Corners"): along a crease polygon c, M1, M2, ... between two corners, the crease points of
// `quad-bspline -p d=4` … `d=12` are at every level the control polygon of the clamped
// uniform degree-d B-spline whose derivatives 2 .. d/2 vanish at the corners, refined by
// inserting every interval's midpoint (Boehm 1980, "Inserting new knots into B-spline
// curves"), computed here independently of the engine; the corners stay; crease rules
// chosen by distance from a corner load, validate and are refused where malformed.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "framework/scheme/scheme_validator.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"
#include "support/sanitizers.h"

using namespace subdiv;

namespace {

// The highest even degree quad-bspline declares, and the round-off its crease-end rows allow:
// the rows next to a corner have weights whose sizes sum to up to 2.1 (d = 8), 8.6 (d = 10),
// 54 (d = 12) and 737 (d = 14), and amplify round-off as much (points of size 12).
constexpr int kHighestEvenDegree = 14;
double round_off(int d) { return d == 14 ? 1e-10 : d == 12 ? 1e-11 : 1e-12; }

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

// Weights of the derivatives 0..count at the start of a clamped B-spline of degree p on the
// control points 0..count: the derivative of a B-spline is one of degree p - 1 with control
// points p (P_{i+1} - P_i) / (t_{i+p+1} - t_{i+1}), and at a clamped start the curve is its
// first control point (de Boor 1978, A Practical Guide to Splines, ch. X).
std::vector<std::vector<double>> start_derivatives(std::vector<double> knots, int p, int count) {
  std::vector<std::vector<double>> rows(size_t(count + 1), std::vector<double>(size_t(count + 1), 0.0));
  for (int i = 0; i <= count; ++i) rows[size_t(i)][size_t(i)] = 1;
  std::vector<std::vector<double>> out{rows[0]};
  for (int j = 1; j <= count; ++j, --p) {
    for (size_t i = 0; i + 1 < rows.size(); ++i)
      for (size_t c = 0; c < rows[i].size(); ++c)
        rows[i][c] = p * (rows[i + 1][c] - rows[i][c]) / (knots[i + size_t(p) + 1] - knots[i + 1]);
    rows.pop_back();
    knots = std::vector<double>(knots.begin() + 1, knots.end() - 1);
    out.push_back(rows[0]);
  }
  return out;
}

// The control points 1..m-1 after the corner c = P_0, given P_m, that make the derivatives
// 2..m (m = d/2) vanish at c on these knots: m - 1 linear conditions.
Polygon end_points(const std::vector<double>& knots, int d, const P3& c, const P3& pm) {
  const int m = d / 2;
  if (m < 2) return {};
  const auto rows = start_derivatives(knots, d, m);
  Eigen::MatrixXd A(m - 1, m - 1), rhs(m - 1, 3);
  for (int j = 2; j <= m; ++j) {
    for (int i = 1; i < m; ++i) A(j - 2, i - 1) = rows[size_t(j)][size_t(i)];
    for (int x = 0; x < 3; ++x) rhs(j - 2, x) = -rows[size_t(j)][0] * c[size_t(x)] - rows[size_t(j)][size_t(m)] * pm[size_t(x)];
  }
  const Eigen::MatrixXd q = A.fullPivLu().solve(rhs);
  Polygon out;
  for (int i = 0; i < m - 1; ++i) out.push_back({q(i, 0), q(i, 1), q(i, 2)});
  return out;
}

// The largest of derivatives 2..m at the start of the curve (ctrl, knots), each relative to
// the sum of its weights' sizes times the end points' spread (round-off's scale: the weights
// grow as the knots get closer).
double start_bend(const Polygon& ctrl, const std::vector<double>& knots, int d) {
  const int m = d / 2;
  const auto rows = start_derivatives(knots, d, m);
  double worst = 0, size = 0;
  for (int i = 0; i <= m; ++i) size = std::max(size, dist(ctrl[size_t(i)], ctrl[0]));
  for (int j = 2; j <= m; ++j) {
    P3 sum{0, 0, 0};
    double scale = 0;
    for (int i = 0; i <= m; ++i) {
      sum = mix(1, sum, rows[size_t(j)][size_t(i)], ctrl[size_t(i)]);
      scale += std::abs(rows[size_t(j)][size_t(i)]);
    }
    worst = std::max(worst, dist(sum, {0, 0, 0}) / (scale * size));
  }
  return worst;
}

std::vector<double> mirrored(const std::vector<double>& knots) {
  std::vector<double> out;
  for (auto it = knots.rbegin(); it != knots.rend(); ++it) out.push_back(knots.back() - *it);
  return out;
}

// The crease polygon's curve: the clamped degree-d B-spline on uniform knots of c, Q_1 ..
// Q_{m-1}, M1, ..., M_{N-1}, Q'_{m-1} .. Q'_1, c' whose derivatives 2 .. m vanish at both
// corners (the Qs follow from that; on a crease of N >= m + 1 edges Q_i = c + i(i + 1)/(m(m +
// 1)) (M1 - c), on a shorter one the far end's clamped knots change them). `levels` times every
// knot interval's midpoint is inserted; returns the control polygon without the Qs, after
// checking that the end condition still holds (a property of the curve). A crease of one edge
// is the segment: no point comes between its corners.
Polygon natural_clamped_refined(const Polygon& p, int d, int levels) {
  if (p.size() == 2) return p;
  const int m = d / 2, intervals = int(p.size()) - 2;
  std::vector<double> knots(size_t(d + 1), 0.0);
  for (int i = 1; i < intervals; ++i) knots.push_back(i);
  knots.insert(knots.end(), size_t(d + 1), double(intervals));
  Polygon ctrl{p.front()};
  for (const P3& q : end_points(knots, d, p.front(), p[1])) ctrl.push_back(q);
  ctrl.insert(ctrl.end(), p.begin() + 1, p.end() - 1);
  const Polygon back = end_points(mirrored(knots), d, p.back(), p[p.size() - 2]);
  ctrl.insert(ctrl.end(), back.rbegin(), back.rend());
  ctrl.push_back(p.back());
  for (int l = 0; l < levels; ++l) {
    std::vector<double> mids;
    for (size_t i = 0; i + 1 < knots.size(); ++i)
      if (knots[i] < knots[i + 1]) mids.push_back(0.5 * (knots[i] + knots[i + 1]));
    for (double t : mids) insert_knot(knots, ctrl, d, t);
  }
  CHECK(start_bend(ctrl, knots, d) < 1e-13);
  CHECK(start_bend(Polygon(ctrl.rbegin(), ctrl.rend()), mirrored(knots), d) < 1e-13);
  Polygon out{ctrl.front()};
  out.insert(out.end(), ctrl.begin() + m, ctrl.end() - m);
  out.push_back(ctrl.back());
  return out;
}

// A 12 x 6 grid, bent, with a crease along grid edges from boundary vertex (0, 2) to (12, 3)
// that turns six times (crease valences 3 and 4 on both sides); its ends have three sharp
// edges (two boundary ones), so they are corners. 15 crease edges: long enough for the rules by
// distance alone up to d = 10 (from 14 edges; d = 12 needs 17 and d = 14 20: short_crease(17) to (21)).
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

Level tagged(const test::Mesh& m, const std::vector<Index>& path, float sharpness = 10.f) {
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Index e = find_edge(L, path[i], path[i + 1]);
    REQUIRE(e != kNone);
    L.edge_sharpness[e] = sharpness;
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

// A grid of height h bent like creased_grid's, with a crease of n edges from bottom boundary
// vertex (4, 0) to the top boundary: up, then right and up in turn, then up; its ends have
// three sharp edges (two boundary ones), so they are corners. n = 1 is one edge across a grid
// of height 1. The grid is at least two columns wider than the crease reaches, so the crease
// never runs along the right boundary.
CreasedGrid short_crease(int n) {
  std::vector<char> moves{'U'};
  for (int i = 0; i + 2 < n; ++i) moves.push_back(i % 2 == 0 ? 'R' : 'U');
  if (n >= 2) moves.push_back('U');
  const int h = int(std::count(moves.begin(), moves.end(), 'U'));
  const int w = std::max(12, 4 + int(std::count(moves.begin(), moves.end(), 'R')) + 2);
  test::Mesh m = test::grid(w, h);
  for (Index v = 0; v < m.vertex_count; ++v) {
    const double x = m.positions[3 * v], y = m.positions[3 * v + 1];
    m.positions[3 * v + 2] = 0.3 * std::sin(0.6 * x) * std::cos(0.7 * y) + 0.03 * x * y;
    m.positions[3 * v] += 0.1 * std::sin(2.1 * v);
    m.positions[3 * v + 1] += 0.08 * std::cos(1.3 * v);
  }
  int i = 4, j = 0;
  std::vector<Index> path{Index(j * (w + 1) + i)};
  for (char c : moves) {
    (c == 'U' ? j : i) += 1;
    path.push_back(Index(j * (w + 1) + i));
  }
  return {m, path};
}

// The crease of `g` refined by quad-bspline with d = 2, 4, ..., 14 (every even degree the
// scheme declares) at levels 1-4 against Boehm's knot insertion of its clamped spline
// (natural_clamped_refined): 2N - 2 points from N, one at each corner, two per crease
// vertex, within round_off(d) (measured 2.4e-12 for d = 12 on points of size 12); both
// corners stay exactly.
void check_clamped_spline(const CreasedGrid& g) {
  Polygon crease;
  for (Index v : g.path) crease.push_back(point(g.mesh.positions, v));
  for (int d = 2; d <= kHighestEvenDegree; d += 2) {
    CAPTURE(d);
    const auto s = load_scheme("quad-bspline", {{"d", std::to_string(d)}});
    RefineOptions options;
    options.levels = 4;
    const Hierarchy h = refine(*s, tagged(g.mesh, g.path), options);
    for (int l = 1; l <= 4; ++l) {
      CAPTURE(l);
      const Polygon expected = natural_clamped_refined(crease, d, l);
      const Polygon got = crease_at(h, l, g.mesh.positions, crease.front());
      REQUIRE(got.size() == expected.size());
      double worst = 0;
      for (size_t i = 0; i < got.size(); ++i) worst = std::max(worst, dist(got[i], expected[i]));
      CHECK(worst < round_off(d));
      CHECK(dist(got.back(), crease.back()) == 0.0);
    }
  }
}

TEST_CASE("quad-bspline crease ends: a crease between corners is the clamped degree-d B-spline with vanishing "
          "derivatives 2..d/2 at the corners, levels 1-4, corners fixed") {
  check_clamped_spline(creased_grid());
}

TEST_CASE("quad-bspline crease ends: short creases of 1-21 edges between two corners are the clamped spline with "
          "the end condition at both ends, levels 1-4") {
  // Up to 19 edges the passes take rules for the crease's length (up to d = 14: from 20 edges
  // the rules by distance alone hold; 20 and 21 check that too).
  for (int n = 1; n <= 21; ++n) {
    if (subdiv_test::thinned_out(n - 1) && n != 21) continue;  // under the sanitizers 1, 4, ..., 19 and 21 edges
    CAPTURE(n);
    check_clamped_spline(short_crease(n));
  }
}

TEST_CASE("quad-bspline crease ends: sharpness 0 on the crease is the smooth scheme, bit for bit, d = 4..14") {
  // An edge of sharpness 0 is smooth: no crease, so no crease vertex finds a corner and no
  // crease-end rule applies; the untagged mesh's points at every level, exactly.
  const CreasedGrid g = creased_grid();
  for (int d = 4; d <= kHighestEvenDegree; d += 2) {
    CAPTURE(d);
    const auto s = load_scheme("quad-bspline", {{"d", std::to_string(d)}});
    RefineOptions options;
    options.levels = 3;
    const Hierarchy smooth = refine(*s, g.mesh.level(), options);
    const Hierarchy zero = refine(*s, tagged(g.mesh, g.path, 0.f), options);
    for (int l = 1; l <= 3; ++l) {
      CAPTURE(l);
      CHECK(zero.levels[size_t(l)].face_vertices == smooth.levels[size_t(l)].face_vertices);
      CHECK(interpolate(zero, l, g.mesh.positions, 3) == interpolate(smooth, l, g.mesh.positions, 3));
    }
  }
}

TEST_CASE("quad-bspline crease ends: a closed crease without corners keeps the uniform rule (Lane-Riesenfeld on the "
          "closed polygon)") {
  // A square loop of 12 interior grid edges around (3..6, 2..5): valence-4 crease vertices,
  // two sharp edges each, no corner.
  test::Mesh m = test::grid(10, 8);
  for (Index v = 0; v < m.vertex_count; ++v) {
    const double x = m.positions[3 * v], y = m.positions[3 * v + 1];
    m.positions[3 * v + 2] = 0.3 * std::sin(0.6 * x) * std::cos(0.7 * y);
    m.positions[3 * v] += 0.1 * std::sin(2.1 * v);
  }
  auto id = [](int i, int j) { return Index(j * 11 + i); };
  std::vector<Index> loop;
  for (int i = 3; i < 6; ++i) loop.push_back(id(i, 2));
  for (int j = 2; j < 5; ++j) loop.push_back(id(6, j));
  for (int i = 6; i > 3; --i) loop.push_back(id(i, 5));
  for (int j = 5; j > 2; --j) loop.push_back(id(3, j));
  std::vector<Index> path = loop;
  path.push_back(loop.front());
  for (int d : {4, 6, 8, 10, 12, 14}) {
    CAPTURE(d);
    const auto s = load_scheme("quad-bspline", {{"d", std::to_string(d)}});
    RefineOptions options;
    options.levels = 2;
    const Hierarchy h = refine(*s, tagged(m, path), options);
    Polygon expected;
    for (Index v : loop) expected.push_back(point(m.positions, v));
    for (int l = 1; l <= 2; ++l) {
      CAPTURE(l);
      // Lane & Riesenfeld 1980: double every point, then average neighbours d times.
      Polygon next;
      for (const P3& q : expected) next.push_back(q), next.push_back(q);
      for (int pass = 0; pass < d; ++pass) {
        Polygon avg;
        for (size_t i = 0; i < next.size(); ++i) avg.push_back(mix(0.5, next[i], 0.5, next[(i + 1) % next.size()]));
        next = avg;
      }
      expected = next;
      const Level& L = h.levels[size_t(l)];
      const auto pos = interpolate(h, l, m.positions, 3);
      std::vector<P3> got;
      for (Index v = 0; v < L.vertex_count; ++v) {
        bool on = false;
        const auto ring = L.ring_edges(v);
        for (Index e : ring) on = on || (!L.edge_on_boundary(e) && L.edge_sharp(e) > 0.f);
        if (on) got.push_back(point(pos, v));
      }
      REQUIRE(got.size() == expected.size());
      double worst = 0;
      for (const P3& q : expected) {
        double nearest = 1e300;
        for (const P3& r : got) nearest = std::min(nearest, dist(q, r));
        worst = std::max(worst, nearest);
      }
      CHECK(worst < 1e-12);
    }
  }
}

TEST_CASE("quad-bspline crease ends: a crease from a corner to a dart (its end inside the surface) refines to "
          "finite points near the mesh, affinely") {
  // Crease from boundary vertex (0, 3) to interior vertex (len, 3): a corner at one end, a
  // dart at the other; the rules by distance from the corner apply, lengths do not (one corner).
  for (int len : {2, 3, 5, 9}) {
    CAPTURE(len);
    test::Mesh m = test::grid(12, 6);
    for (Index v = 0; v < m.vertex_count; ++v) m.positions[3 * v + 2] = 0.3 * std::sin(0.6 * m.positions[3 * v] + 0.2 * v);
    std::vector<Index> path;
    for (int i = 0; i <= len; ++i) path.push_back(Index(3 * 13 + i));
    test::Mesh moved = m;
    for (Index v = 0; v < m.vertex_count; ++v) moved.positions[3 * v] += 5, moved.positions[3 * v + 2] -= 2;
    for (int d : {4, 6, 8, 10, 12, 14}) {
      CAPTURE(d);
      const auto s = load_scheme("quad-bspline", {{"d", std::to_string(d)}});
      RefineOptions options;
      options.levels = 3;
      const Hierarchy h = refine(*s, tagged(m, path), options);
      const auto a = interpolate(h, 3, m.positions, 3), b = interpolate(h, 3, moved.positions, 3);
      double worst = 0, reach = 0;
      for (size_t v = 0; v < a.size() / 3; ++v) {
        const P3 p = point(a, Index(v));
        worst = std::max(worst, dist(mix(1, point(b, Index(v)), -1, p), {5, 0, -2}));
        // the grid spans [0, 12] x [0, 6] x [-0.3, 0.3]: no point strays out of it
        reach = std::max({reach, -p[0], p[0] - 12, -p[1], p[1] - 6, std::abs(p[2]) - 0.3});
      }
      CHECK(std::isfinite(worst));
      CHECK(worst < 1e-12);
      CHECK(reach < 1e-9);
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

TEST_CASE("quad-bspline crease ends: without the rules for a crease's length a short crease is not the clamped "
          "spline") {
  // quad-bspline with its "length" entries left out: on a crease of 3 edges the rules by
  // distance alone read past the far corner, so the test of short creases above could fail.
  std::ifstream in(std::string(SUBDIV_SOURCE_DIR) + "/schemes/quad-bspline.json");
  nlohmann::json j = nlohmann::json::parse(in);
  for (auto& step : j["steps"])
    if (step.contains("smooth") && step["smooth"]["vertex"].contains("crease-ends")) {
      nlohmann::json kept = nlohmann::json::array();
      for (const auto& entry : step["smooth"]["vertex"]["crease-ends"])
        if (!entry.contains("length")) kept.push_back(entry);
      step["smooth"]["vertex"]["crease-ends"] = kept;
    }
  const auto s = load_scheme_text(j.dump(), "no-lengths.json", {{"d", "4"}});
  const CreasedGrid g = short_crease(3);
  Polygon crease;
  for (Index v : g.path) crease.push_back(point(g.mesh.positions, v));
  RefineOptions options;
  options.levels = 1;
  const Hierarchy h = refine(*s, tagged(g.mesh, g.path), options);
  const Polygon expected = natural_clamped_refined(crease, 4, 1);
  const Polygon got = crease_at(h, 1, g.mesh.positions, crease.front());
  REQUIRE(got.size() == expected.size());
  double worst = 0;
  for (size_t i = 0; i < got.size(); ++i) worst = std::max(worst, dist(got[i], expected[i]));
  CHECK(worst > 1e-3);
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
  CHECK(zero.rfind("ends.json:3: steps[1].smooth.vertex.crease-ends[0].distance: 0 is outside [1, 24]", 0) == 0);
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
  CHECK(load_error(with_ends(R"([{"distance": 1, "length": 1, "rule": [{"at": "self", "w": "1"}]}])"))
            .find("crease-ends[0].length: 1 is outside [2, 49]") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 3, "length": 5, "rule": [{"at": "self", "w": "1"}]}])"))
            .find("crease-ends[0].distance: 3 is outside [1, 2]") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 1, "length": 3, "rule": [{"at": "crease-point", "step": 3, "w": "1"}]}])"))
            .find("rule[0].step: step 3 reaches past the far corner, which is 2 crease edge(s) away") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 2, "length": 4, "rule": [{"at": "crease-point", "step": -1, "w": "1/4"},
                                                                      {"at": "self", "w": "3/4"}]}])"))
            .find("the middle vertex of a crease of 4 edges is 2 edges from both corners") != std::string::npos);
  CHECK(load_error(with_ends(R"([{"distance": 1, "length": 3, "rule": [{"at": "self", "w": "1"}]},
                                 {"distance": 1, "length": 3, "rule": [{"at": "self", "w": "1"}]}])"))
            .find("distance 1 on creases of length 3 has a rule already") != std::string::npos);
  // Edge and dual corner rules have no crease-ends: their points next to a corner take the
  // crease and corner contexts.
  const std::string dual = R"json({"name": "c", "faces": "any", "split": "dual", "rules": {"corner": {
      "smooth": [{"sum": "vertices", "w": "1/k"}],
      "crease-ends": [{"distance": 1, "rule": [{"at": "self", "w": "1"}]}]}}})json";
  CHECK(load_error(dual).find("rules.corner.crease-ends: crease-ends belong to vertex rules") != std::string::npos);
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
