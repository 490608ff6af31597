// Creases of dual schemes (docs/features.md, "Creases in dual schemes"): the points a dual
// split makes along a sharp crease are the crease polygon's curve-scheme refinement —
// Chaikin 1974 (3/4 a + 1/4 b, 1/4 a + 3/4 b) for Doo-Sabin (Doo & Sabin 1978) and the
// biquadratic B-spline, the degree-d B-spline (Lane & Riesenfeld 1980) for even-degree quad
// B-splines — for any crease shape and valence; corners stay; sharpness 0 is the smooth
// scheme and fractional sharpness lies strictly between (DeRose, Kass & Truong 1998).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <string>

#include "framework/interpolation/limit_selection.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;

namespace {

using P3 = std::array<double, 3>;
using Polygon = std::vector<P3>;

// Chaikin 1974 on a closed polygon: two points per segment at 1/4 and 3/4.
Polygon chaikin_closed(const Polygon& p) {
  Polygon q;
  for (size_t i = 0; i < p.size(); ++i) {
    const P3& a = p[i];
    const P3& b = p[(i + 1) % p.size()];
    q.push_back({0.75 * a[0] + 0.25 * b[0], 0.75 * a[1] + 0.25 * b[1], 0.75 * a[2] + 0.25 * b[2]});
    q.push_back({0.25 * a[0] + 0.75 * b[0], 0.25 * a[1] + 0.75 * b[1], 0.25 * a[2] + 0.75 * b[2]});
  }
  return q;
}

// The control polygon of a B-spline of degree p after inserting knot t once (Boehm 1980,
// "Inserting new knots into B-spline curves"): for the span t_k <= t < t_{k+1},
// Q_i = (1 - a_i) P_{i-1} + a_i P_i with a_i = (t - t_i) / (t_{i+p} - t_i), k-p+1 <= i <= k.
void insert_knot(std::vector<double>& knots, Polygon& ctrl, int p, double t) {
  size_t k = 0;
  while (!(knots[k] <= t && t < knots[k + 1])) ++k;
  Polygon q;
  for (size_t i = 0; i <= ctrl.size(); ++i) {
    if (i + p <= k) q.push_back(ctrl[i]);
    else if (i > k) q.push_back(ctrl[i - 1]);
    else {
      const double a = (t - knots[i]) / (knots[i + p] - knots[i]);
      P3 x;
      for (int c = 0; c < 3; ++c) x[c] = (1 - a) * ctrl[i - 1][c] + a * ctrl[i][c];
      q.push_back(x);
    }
  }
  knots.insert(knots.begin() + ptrdiff_t(k) + 1, t);
  ctrl = q;
}

// The open quadratic B-spline through the polygon's ends: clamped uniform knots
// 0, 0, 0, 1, ..., n - 2, n - 2, n - 2 (n control points), refined `levels` times by
// inserting every interval's midpoint; returns the control polygon.
Polygon clamped_quadratic_refined(const Polygon& p, int levels) {
  std::vector<double> knots{0, 0};
  for (size_t i = 0; i + 1 < p.size(); ++i) knots.push_back(double(i));
  knots.push_back(knots.back()), knots.push_back(knots.back());
  Polygon ctrl = p;
  for (int l = 0; l < levels; ++l) {
    std::vector<double> mids;
    for (size_t i = 0; i + 1 < knots.size(); ++i)
      if (knots[i] < knots[i + 1]) mids.push_back(0.5 * (knots[i] + knots[i + 1]));
    for (double t : mids) insert_knot(knots, ctrl, 2, t);
  }
  return ctrl;
}

// Uniform B-spline of degree d on a closed polygon by Lane & Riesenfeld 1980: double every
// point, then average neighbours d times.
Polygon lane_riesenfeld_closed(const Polygon& p, int d) {
  Polygon q;
  for (const P3& x : p) q.push_back(x), q.push_back(x);
  for (int pass = 0; pass < d; ++pass) {
    Polygon r(q.size());
    for (size_t i = 0; i < q.size(); ++i)
      for (int c = 0; c < 3; ++c) r[i][c] = 0.5 * (q[i][c] + q[(i + 1) % q.size()][c]);
    q = r;
  }
  return q;
}

// The mid-edge curve rule (Peters & Reif 1997's split on a polygon; the `two-point` curve's
// rule 1): every edge's midpoint, in order, so a closed polygon keeps its number of points.
Polygon midpoints_closed(const Polygon& p) {
  Polygon q;
  for (size_t i = 0; i < p.size(); ++i) {
    const P3& a = p[i];
    const P3& b = p[(i + 1) % p.size()];
    q.push_back({0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])});
  }
  return q;
}

double dist(const P3& a, const P3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// A quad torus (8 x 6) made irregular along the crease loop j = 0: two quads merged into
// hexagons (crease valence 3, one on each side) and quads split into triangles (valence 5
// and 6), every vertex moved off the torus so the crease is no plane curve.
struct CreasedTorus {
  test::Mesh mesh;
  std::vector<Index> loop;  // the crease polygon, in order
};

CreasedTorus creased_torus() {
  const int nu = 8, nv = 6;
  test::Mesh t = test::torus(nu, nv);
  for (Index v = 0; v < t.vertex_count; ++v) {
    t.positions[3 * v + 0] += 0.15 * std::sin(1.7 * v);
    t.positions[3 * v + 1] += 0.12 * std::cos(2.3 * v);
    t.positions[3 * v + 2] += 0.2 * std::sin(0.9 * v + 1.0);
  }
  auto id = [&](int i, int j) { return Index(((j + nv) % nv) * nu + (i + nu) % nu); };
  test::Mesh m;
  m.vertex_count = t.vertex_count;
  m.positions = t.positions;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (j == 0 && i == 0)  // merged with (1, 0): crease vertex (1, 0) has valence 3
        m.add_face({id(0, 0), id(1, 0), id(2, 0), id(2, 1), id(1, 1), id(0, 1)});
      else if (j == 0 && i == 1) continue;
      else if (j == 0 && (i == 3 || i == 5)) {  // fans from the crease vertex: valences 5 and 6
        m.add_face({id(i, 0), id(i + 1, 0), id(i + 1, 1)});
        m.add_face({id(i, 0), id(i + 1, 1), id(i, 1)});
      } else if (j == nv - 1 && i == 4) {
        m.add_face({id(5, 0), id(4, 0), id(4, nv - 1)});
        m.add_face({id(5, 0), id(4, nv - 1), id(5, nv - 1)});
      } else if (j == nv - 1 && i == 6)  // merged with (7, nv - 1): crease vertex (7, 0) valence 3
        m.add_face({id(6, nv - 1), id(7, nv - 1), id(0, nv - 1), id(0, 0), id(7, 0), id(6, 0)});
      else if (j == nv - 1 && i == 7) continue;
      else m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  CreasedTorus c{m, {}};
  for (int i = 0; i < nu; ++i) c.loop.push_back(id(i, 0));
  return c;
}

Level tagged(const test::Mesh& m, const std::vector<Index>& polygon, bool closed, float s) {
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (size_t i = 0; i + (closed ? 0 : 1) < polygon.size(); ++i) {
    const Index e = find_edge(L, polygon[i], polygon[(i + 1) % polygon.size()]);
    REQUIRE(e != kNone);
    L.edge_sharpness[e] = s;
  }
  return L;
}

Polygon points_of(const std::vector<Index>& ids, const std::vector<double>& pos) {
  Polygon p;
  for (Index v : ids) p.push_back({pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]});
  return p;
}

// The interior edges of L tagged sharp, chained from `start` (a closed loop if start is kNone).
std::vector<Index> crease_chain(const Level& L, Index start) {
  std::vector<std::vector<Index>> next(size_t(L.vertex_count));
  for (Index e = 0; e < L.edge_count(); ++e)
    if (!L.edge_on_boundary(e) && L.edge_sharp(e) > 0.f) {
      next[L.edge_vertices[2 * e]].push_back(L.edge_vertices[2 * e + 1]);
      next[L.edge_vertices[2 * e + 1]].push_back(L.edge_vertices[2 * e]);
    }
  Index v = start;
  if (v == kNone)
    for (Index u = 0; u < L.vertex_count && v == kNone; ++u)
      if (!next[u].empty()) v = u;
  std::vector<Index> chain{v};
  Index prev = kNone;
  while (true) {
    Index to = kNone;
    for (Index w : next[v])
      if (w != prev) to = w;
    if (to == kNone || to == chain.front()) break;
    if (chain.size() > size_t(L.vertex_count)) break;
    chain.push_back(to);
    prev = v, v = to;
  }
  return chain;
}

// The refined crease equals `expected` up to a cyclic shift and the direction of travel.
void check_same_closed_polygon(const Polygon& got, const Polygon& expected, double tol) {
  REQUIRE(got.size() == expected.size());
  const size_t n = got.size();
  size_t start = 0;
  for (size_t i = 1; i < n; ++i)
    if (dist(expected[i], got[0]) < dist(expected[start], got[0])) start = i;
  const int dir = dist(expected[(start + 1) % n], got[1]) < dist(expected[(start + n - 1) % n], got[1]) ? 1 : -1;
  double worst = 0;
  for (size_t i = 0; i < n; ++i) worst = std::max(worst, dist(got[i], expected[(start + n + dir * long(i)) % n]));
  CHECK(worst < tol);
}

bool watertight(const Level& L) {
  for (Index e = 0; e < L.edge_count(); ++e)
    if (L.edge_on_boundary(e) || L.non_manifold_edge(e)) return false;
  return L.manifold();
}

}  // namespace

TEST_CASE("dual crease: a crease loop of valences 3-6, not planar, is Chaikin's refinement at levels 1-4") {
  const CreasedTorus t = creased_torus();
  for (const std::string scheme : {"doo-sabin", "doo-sabin-centroid"}) {
    CAPTURE(scheme);
    const Level base = tagged(t.mesh, t.loop, true, 10.f);
    std::vector<int> valences;
    for (Index v : t.loop) valences.push_back(base.valence(v));
    CHECK(*std::min_element(valences.begin(), valences.end()) == 3);
    CHECK(*std::max_element(valences.begin(), valences.end()) == 6);
    const auto s = load_scheme(scheme, {});
    RefineOptions options;
    options.levels = 4;
    const Hierarchy h = refine(*s, base, options);
    Polygon expected = points_of(t.loop, t.mesh.positions);
    for (int l = 1; l <= 4; ++l) {
      CAPTURE(l);
      expected = chaikin_closed(expected);
      const Level& L = h.levels[size_t(l)];
      const auto pos = interpolate(h, l, t.mesh.positions, 3);
      check_same_closed_polygon(points_of(crease_chain(L, kNone), pos), expected, 1e-12);
      CHECK(watertight(L));
      CHECK(euler_characteristic(L) == 0);  // a torus
    }
  }
}

// The crease loop of `t` at levels 1..levels of `h` is Chaikin's refinement of the crease
// polygon, level by level.
namespace {
void check_chaikin_crease_loop(const Hierarchy& h, const CreasedTorus& t, int levels) {
  Polygon expected = points_of(t.loop, t.mesh.positions);
  for (int l = 1; l <= levels; ++l) {
    CAPTURE(l);
    expected = chaikin_closed(expected);
    const auto pos = interpolate(h, l, t.mesh.positions, 3);
    check_same_closed_polygon(points_of(crease_chain(h.levels[size_t(l)], kNone), pos), expected, 1e-12);
  }
}
}  // namespace

TEST_CASE("dual crease: a stated corner crease rule gives both points of a split corner, mirrored on the arriving edge") {
  // Chaikin's rule 0 (3/4 v + 1/4 next) stated as the `crease` corner rule instead of by
  // "curve": on the arriving edge it applies mirrored (3/4 v + 1/4 prev), so the crease loop,
  // whose valence-3 vertices have corners between two sharp edges, is Chaikin's polygon again.
  const std::string text = R"json({
    "name": "doo-sabin-stated", "split": "dual", "faces": "any",
    "rules": {"corner": {
      "smooth": [{"sum": "vertices", "w": "j == 0 ? (k + 5)/(4*k) : (3 + 2*cos(2*pi*j/k))/(4*k)"}],
      "crease": [{"sum": "vertices", "w": "j == 0 ? 3/4 : (j == 1 ? 1/4 : 0)"}],
      "corner": [{"at": "self", "w": "1"}]}}})json";
  const auto s = load_scheme_text(text, "stated.json");
  const CreasedTorus t = creased_torus();
  RefineOptions options;
  options.levels = 3;
  const Hierarchy h = refine(*s, tagged(t.mesh, t.loop, true, 10.f), options);
  check_chaikin_crease_loop(h, t, 3);
}

TEST_CASE("mid-edge crease: a crease loop of valences 3-6 is the polygon of its edge midpoints at levels 1-4") {
  const CreasedTorus t = creased_torus();
  const auto s = load_scheme("mid-edge", {});
  RefineOptions options;
  options.levels = 4;
  const Hierarchy h = refine(*s, tagged(t.mesh, t.loop, true, 10.f), options);
  Polygon expected = points_of(t.loop, t.mesh.positions);
  for (int l = 1; l <= 4; ++l) {
    CAPTURE(l);
    expected = midpoints_closed(expected);
    const Level& L = h.levels[size_t(l)];
    const auto pos = interpolate(h, l, t.mesh.positions, 3);
    const std::vector<Index> chain = crease_chain(L, kNone);
    CHECK(chain.size() == t.loop.size());  // the crease is one loop of as many points
    check_same_closed_polygon(points_of(chain, pos), expected, 1e-12);
    CHECK(watertight(L));
    CHECK(euler_characteristic(L) == 0);  // a torus
  }
  // Untagged, the V-faces of the loop's vertices are whole and the crease is no polyline of
  // the child: the loop's midpoints are joined only through F-faces, never consecutively by
  // an edge closing a sector, so the test above can fail.
  const Hierarchy smooth = refine(*s, t.mesh.level(), options);
  const Level& C = smooth.levels[1];
  int joined = 0;
  const Level base = t.mesh.level();
  for (size_t i = 0; i < t.loop.size(); ++i) {
    const Index a = find_edge(base, t.loop[i], t.loop[(i + 1) % t.loop.size()]);
    const Index b = find_edge(base, t.loop[(i + 1) % t.loop.size()], t.loop[(i + 2) % t.loop.size()]);
    joined += find_edge(C, a, b) != kNone;  // child vertex e is parent edge e's midpoint
  }
  CHECK(joined < int(t.loop.size()));
}

TEST_CASE("mid-edge crease: semi-sharp creases keep the smooth topology and decay to it") {
  const CreasedTorus t = creased_torus();
  const auto s = load_scheme("mid-edge", {});
  RefineOptions options;
  options.levels = 3;
  const Hierarchy smooth = refine(*s, t.mesh.level(), options);
  const Hierarchy half = refine(*s, tagged(t.mesh, t.loop, true, 0.5f), options);
  const Hierarchy decays = refine(*s, tagged(t.mesh, t.loop, true, 1.5f), options);
  // s < 1: the smooth faces; s = 1.5: sectors at level 1 only, then faces as many as smooth.
  CHECK(half.levels[1].face_offsets == smooth.levels[1].face_offsets);
  CHECK(half.levels[1].face_vertices == smooth.levels[1].face_vertices);
  CHECK(decays.levels[1].face_count() > smooth.levels[1].face_count());
  float most = 0.f;
  for (float x : decays.levels[1].edge_sharpness) most = std::max(most, x);
  CHECK(most == 0.5f);
  for (int l = 1; l <= 3; ++l) CHECK(watertight(decays.levels[size_t(l)]));
}

TEST_CASE("dual crease: even-degree quad B-splines follow the degree-d B-spline (Lane-Riesenfeld) along a crease loop") {
  const CreasedTorus t = creased_torus();
  for (int d : {2, 4, 6}) {
    CAPTURE(d);
    const auto s = load_scheme("quad-bspline", {{"d", std::to_string(d)}});
    RefineOptions options;
    options.levels = 3;
    const Hierarchy h = refine(*s, tagged(t.mesh, t.loop, true, 10.f), options);
    Polygon expected = points_of(t.loop, t.mesh.positions);
    for (int l = 1; l <= 3; ++l) {
      CAPTURE(l);
      expected = lane_riesenfeld_closed(expected, d);
      const auto pos = interpolate(h, l, t.mesh.positions, 3);
      check_same_closed_polygon(points_of(crease_chain(h.levels[size_t(l)], kNone), pos), expected, 1e-12);
      CHECK(watertight(h.levels[size_t(l)]));
    }
  }
}

// A 6 x 6 grid, bent, with a zigzag crease from boundary vertex (0, 2) to (6, 4): its ends
// have three sharp edges (two boundary ones), so they are corners.
struct ZigzagGrid {
  test::Mesh mesh;
  std::vector<Index> path;
};

ZigzagGrid zigzag_grid() {
  test::Mesh m = test::grid(6, 6);
  for (Index v = 0; v < m.vertex_count; ++v) {
    const double x = m.positions[3 * v], y = m.positions[3 * v + 1];
    m.positions[3 * v + 2] = 0.3 * std::sin(x) * std::cos(0.7 * y) + 0.05 * x * y;
    m.positions[3 * v] += 0.1 * std::sin(2.1 * v);
  }
  auto id = [](int i, int j) { return Index(j * 7 + i); };
  const std::vector<Index> path = {id(0, 2), id(1, 2), id(2, 3), id(3, 3), id(4, 3), id(4, 4), id(5, 4), id(6, 4)};
  // id(1,2) -> id(2,3) is a diagonal: add it by splitting the quad (1,2)-(2,2)-(2,3)-(1,3).
  test::Mesh g;
  g.vertex_count = m.vertex_count;
  g.positions = m.positions;
  for (Index f = 0; f + 1 < Index(m.offsets.size()); ++f) {
    const Index* c = &m.corners[m.offsets[f]];
    if (c[0] == id(1, 2)) {
      g.add_face({c[0], c[1], c[2]});
      g.add_face({c[0], c[2], c[3]});
    } else {
      g.add_face({c[0], c[1], c[2], c[3]});
    }
  }
  return {g, path};
}

TEST_CASE("dual crease: a crease between two corners keeps them and is the open quadratic B-spline through them, "
          "levels 1-4") {
  const ZigzagGrid z = zigzag_grid();
  const test::Mesh& g = z.mesh;
  const std::vector<Index>& path = z.path;
  Level base;
  base = tagged(g, path, false, 10.f);
  const auto s = load_scheme("doo-sabin", {});
  RefineOptions options;
  options.levels = 4;
  const Hierarchy h = refine(*s, base, options);
  const Polygon crease = points_of(path, g.positions);
  const P3 first = crease.front(), last = crease.back();
  for (int l = 1; l <= 4; ++l) {
    CAPTURE(l);
    const Polygon expected = clamped_quadratic_refined(crease, l);
    const Level& L = h.levels[size_t(l)];
    const auto pos = interpolate(h, l, g.positions, 3);
    // Start at the child vertex on the first corner.
    Index start = kNone;
    for (Index v = 0; v < L.vertex_count; ++v)
      if (dist({pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]}, first) < 1e-14) start = v;
    REQUIRE(start != kNone);
    const Polygon got = points_of(crease_chain(L, start), pos);
    REQUIRE(got.size() == expected.size());
    double worst = 0;
    for (size_t i = 0; i < got.size(); ++i) worst = std::max(worst, dist(got[i], expected[i]));
    CHECK(worst < 1e-12);
    CHECK(dist(got.back(), last) == 0.0);  // both corners stay exactly
    CHECK(euler_characteristic(L) == euler_characteristic(base));
  }
}

TEST_CASE("dual crease: sharpness 0 is the smooth scheme; fractional sharpness lies strictly between") {
  const CreasedTorus t = creased_torus();
  const auto s = load_scheme("doo-sabin", {});
  RefineOptions options;
  options.levels = 1;
  const Level plain = t.mesh.level();
  const Hierarchy smooth = refine(*s, plain, options);
  const Hierarchy zero = refine(*s, tagged(t.mesh, t.loop, true, 0.f), options);
  const auto p_smooth = interpolate(smooth, 1, t.mesh.positions, 3);
  CHECK(interpolate(zero, 1, t.mesh.positions, 3) == p_smooth);
  for (float sharp : {0.25f, 0.5f, 0.75f}) {
    CAPTURE(sharp);
    const Level L = tagged(t.mesh, t.loop, true, sharp);
    const Hierarchy half = refine(*s, L, options);
    const auto p = interpolate(half, 1, t.mesh.positions, 3);
    REQUIRE(p.size() == p_smooth.size());  // a semi-sharp edge keeps the smooth topology
    int checked = 0;
    // Corners beside exactly one crease edge: (1 - s) smooth + s (3/4 v + 1/4 next) or
    // (1 - s) smooth + s (1/4 prev + 3/4 v).
    for (Index f = 0; f < L.face_count(); ++f) {
      const int k = L.face_size(f);
      for (int c = 0; c < k; ++c) {
        const Index v = L.face(f)[c], next = L.face(f)[(c + 1) % k], prev = L.face(f)[(c + k - 1) % k];
        const bool out = L.edge_sharp(L.face_edge_list(f)[c]) > 0, in = L.edge_sharp(L.face_edge_list(f)[(c + k - 1) % k]) > 0;
        if (out == in) continue;
        const Index w = out ? next : prev;
        const Index child = L.face_offsets[f] + c;
        P3 sharp_point, smooth_point, got;
        for (int i = 0; i < 3; ++i) {
          sharp_point[i] = 0.75 * t.mesh.positions[3 * v + i] + 0.25 * t.mesh.positions[3 * w + i];
          smooth_point[i] = p_smooth[3 * child + i];
          got[i] = p[3 * child + i];
        }
        for (int i = 0; i < 3; ++i)
          CHECK(got[i] == doctest::Approx((1 - sharp) * smooth_point[i] + sharp * sharp_point[i]).epsilon(1e-13));
        CHECK(dist(got, smooth_point) > 1e-6);
        CHECK(dist(got, sharp_point) > 1e-6);
        ++checked;
      }
    }
    CHECK(checked >= 20);
  }
}

TEST_CASE("dual crease: semi-sharp creases decay one unit per level and stay watertight") {
  const CreasedTorus t = creased_torus();
  const auto s = load_scheme("doo-sabin", {});
  RefineOptions options;
  options.levels = 4;
  const Hierarchy h = refine(*s, tagged(t.mesh, t.loop, true, 2.5f), options);
  // Sharp (>= 1) at levels 0 and 1: glued creases; 0.5 at level 2 (blended on smooth
  // topology); smooth from level 3 on.
  float expected[] = {2.5f, 1.5f, 0.5f, 0.f, 0.f};
  for (int l = 0; l <= 4; ++l) {
    CAPTURE(l);
    const Level& L = h.levels[size_t(l)];
    float most = 0.f;
    for (Index e = 0; e < Index(L.edge_sharpness.size()); ++e) most = std::max(most, L.edge_sharpness[e]);
    CHECK(most == expected[l]);
    CHECK(watertight(L));
    CHECK(euler_characteristic(L) == 0);
  }
}

// The positive edge sharpness values of a level, sorted.
std::vector<float> sharpness_values(const Level& L) {
  std::vector<float> out;
  for (float x : L.edge_sharpness)
    if (x > 0.f) out.push_back(x);
  std::sort(out.begin(), out.end());
  return out;
}

TEST_CASE("dual crease: --crease-method chaikin decays the crease as DeRose, Kass & Truong 1998's Chaikin rule") {
  // Crease loop edge i has sharpness s_i = 1.5 + 0.375 i (all semi-sharp, >= 1). Chaikin's
  // rule (DeRose, Kass & Truong 1998, sec. 4.2; OpenSubdiv's Sdc::Crease): the child of edge
  // e next to vertex v has 3/4 s_e + 1/4 (mean of v's other semi-sharp edges) - 1; uniform:
  // s_e - 1. A dual child edge along e_i lies in its middle (the mean at its two ends); the
  // edge across loop vertex p_i joins e_(i-1) and e_i there (the mean of their values at p_i).
  const CreasedTorus t = creased_torus();
  const size_t n = t.loop.size();
  std::vector<float> sharp(n);
  for (size_t i = 0; i < n; ++i) sharp[i] = 1.5f + 0.375f * float(i);
  Level base = tagged(t.mesh, t.loop, true, 0.f);
  for (size_t i = 0; i < n; ++i) base.edge_sharpness[find_edge(base, t.loop[i], t.loop[(i + 1) % n])] = sharp[i];
  auto chaikin = [](float s, float other) { return std::max(0.f, 0.75f * s + 0.25f * other - 1.f); };
  auto uniform = [](float s, float) { return s - 1.f; };
  for (const std::string scheme : {"doo-sabin", "mid-edge"}) {
    for (bool use_chaikin : {false, true}) {
      CAPTURE(scheme);
      CAPTURE(use_chaikin);
      std::vector<float> expected;
      for (size_t i = 0; i < n; ++i) {
        const float prev = sharp[(i + n - 1) % n], here = sharp[i], next = sharp[(i + 1) % n];
        const auto rule = [&](float s, float o) { return use_chaikin ? chaikin(s, o) : uniform(s, o); };
        if (scheme == "doo-sabin") expected.push_back(0.5f * (rule(here, prev) + rule(here, next)));
        expected.push_back(0.5f * (rule(prev, here) + rule(here, prev)));  // across p_i
      }
      std::sort(expected.begin(), expected.end());
      RefineOptions options;
      options.levels = 1;
      options.features.crease_method = use_chaikin ? CreaseMethod::Chaikin : CreaseMethod::Uniform;
      const Hierarchy h = refine(*load_scheme(scheme, {}), base, options);
      const std::vector<float> got = sharpness_values(h.levels[1]);
      REQUIRE(got.size() == expected.size());
      for (size_t i = 0; i < got.size(); ++i) CHECK(got[i] == doctest::Approx(expected[i]).epsilon(1e-6));
    }
  }
}

TEST_CASE("dual crease: a tagged corner inside a surface stays at every level") {
  test::Mesh m = test::torus(8, 6);
  Level L = m.level();
  L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
  L.vertex_sharpness[10] = 10.f;
  const auto s = load_scheme("doo-sabin", {});
  RefineOptions options;
  options.levels = 3;
  const Hierarchy h = refine(*s, L, options);
  for (int l = 1; l <= 3; ++l) {
    const auto pos = interpolate(h, l, m.positions, 3);
    bool found = false;
    for (Index v = 0; v < h.levels[size_t(l)].vertex_count; ++v)
      found |= pos[3 * v] == m.positions[30] && pos[3 * v + 1] == m.positions[31] && pos[3 * v + 2] == m.positions[32];
    CHECK(found);
    CHECK(watertight(h.levels[size_t(l)]));
    CHECK(euler_characteristic(h.levels[size_t(l)]) == 0);
  }
}

// Cox & de Boor: the degree-2 B-spline with knots t at parameter x (t_k <= x < t_{k+1}).
P3 quadratic_bspline_at(const std::vector<double>& t, const Polygon& ctrl, double x) {
  size_t k = 2;
  while (!(t[k] <= x && x < t[k + 1])) ++k;
  Polygon d(ctrl.begin() + ptrdiff_t(k) - 2, ctrl.begin() + ptrdiff_t(k) + 1);
  for (int r = 1; r <= 2; ++r)
    for (int j = 2; j >= r; --j) {
      const size_t i = k - 2 + size_t(j);
      const double a = (x - t[i]) / (t[i + 3 - size_t(r)] - t[i]);
      for (int c = 0; c < 3; ++c) d[size_t(j)][c] = (1 - a) * d[size_t(j) - 1][c] + a * d[size_t(j)][c];
    }
  return d[2];
}

std::vector<double> limit_points_of(const char* scheme, const Level& L, const std::vector<double>& positions) {
  const LimitChoice c = select_limit(load_scheme_sequence(scheme, 1, {}), L);
  std::vector<double> got(positions.size());
  c.evaluator->limit_points(L, positions, got);
  return got;
}

TEST_CASE("dual crease: a tagged corner is its own limit point") {
  test::Mesh m = test::torus(8, 6);
  Level L = m.level();
  L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
  L.vertex_sharpness[10] = 10.f;
  const auto got = limit_points_of("doo-sabin", L, m.positions);
  for (int i = 0; i < 3; ++i) CHECK(got[30 + i] == m.positions[30 + i]);
}

TEST_CASE("dual crease: limit points on a crease loop lie on the quadratic B-spline of the crease polygon") {
  // Chaikin's crease converges to the uniform quadratic B-spline of the crease polygon, whose
  // point at control point v's parameter (its Greville abscissa, between v's two knots) is
  // (p + 6 v + q) / 8 (de Boor: the basis functions there are 1/8, 3/4, 1/8).
  const CreasedTorus t = creased_torus();
  const Level L = tagged(t.mesh, t.loop, true, 10.f);
  for (const char* scheme : {"doo-sabin", "doo-sabin-centroid"}) {
    CAPTURE(scheme);
    const auto got = limit_points_of(scheme, L, t.mesh.positions);
    const size_t n = t.loop.size();
    for (size_t i = 0; i < n; ++i) {
      const Index p = t.loop[(i + n - 1) % n], v = t.loop[i], q = t.loop[(i + 1) % n];
      for (int c = 0; c < 3; ++c)
        CHECK(got[size_t(3 * v + c)] == doctest::Approx((t.mesh.positions[size_t(3 * p + c)] + 6 * t.mesh.positions[size_t(3 * v + c)] +
                                                       t.mesh.positions[size_t(3 * q + c)]) / 8)
                                            .epsilon(1e-13));
    }
    // And refinement converges there: the crease polygon after 14 Chaikin steps passes within
    // its segment length of each limit point.
    Polygon fine = points_of(t.loop, t.mesh.positions);
    for (int l = 0; l < 14; ++l) fine = chaikin_closed(fine);
    for (Index v : t.loop) {
      double nearest = 1e9;
      for (const P3& x : fine) nearest = std::min(nearest, dist(x, {got[size_t(3 * v)], got[size_t(3 * v + 1)], got[size_t(3 * v + 2)]}));
      CHECK(nearest < 1e-3);
    }
  }
}

TEST_CASE("dual crease: limit points on a crease between corners lie on the clamped quadratic B-spline; "
          "boundary vertices on the boundary's") {
  const ZigzagGrid z = zigzag_grid();
  const Level L = tagged(z.mesh, z.path, false, 10.f);
  const auto got = limit_points_of("doo-sabin", L, z.mesh.positions);
  // Clamped knots 0, 0, 0, 1, ..., m - 2, m - 2, m - 2 for m control points (the crease ends
  // at its corners); control point i sits at its Greville abscissa (t_{i+1} + t_{i+2}) / 2.
  const Polygon ctrl = points_of(z.path, z.mesh.positions);
  std::vector<double> knots{0, 0};
  for (size_t i = 0; i + 1 < ctrl.size(); ++i) knots.push_back(double(i));
  knots.push_back(knots.back()), knots.push_back(knots.back());
  for (size_t i = 0; i < ctrl.size(); ++i) {
    CAPTURE(i);
    const double x = std::min(0.5 * (knots[i + 1] + knots[i + 2]), knots.back() - 1e-15);
    const P3 want = quadratic_bspline_at(knots, ctrl, x);
    const Index v = z.path[i];
    CHECK(dist({got[size_t(3 * v)], got[size_t(3 * v + 1)], got[size_t(3 * v + 2)]}, want) < 1e-12);
  }
  // A boundary vertex with two faces (the grid's bottom row, away from the corners) follows
  // the boundary's Chaikin curve: (p + 6 v + q) / 8.
  for (Index v : {Index(2), Index(3), Index(4)})
    for (int c = 0; c < 3; ++c)
      CHECK(got[size_t(3 * v + c)] ==
            doctest::Approx((z.mesh.positions[size_t(3 * (v - 1) + c)] + 6 * z.mesh.positions[size_t(3 * v + c)] +
                             z.mesh.positions[size_t(3 * (v + 1) + c)]) / 8)
                .epsilon(1e-13));
}

TEST_CASE("dual crease: a vertex ending a crease (a dart) is refused by name") {
  const CreasedTorus t = creased_torus();
  const std::vector<Index> open(t.loop.begin(), t.loop.begin() + 3);
  std::string message;
  try {
    (void)select_limit(load_scheme_sequence("doo-sabin", 1, {}), tagged(t.mesh, open, false, 10.f));
  } catch (const Error& e) {
    message = e.what();
  }
  CHECK(message.find("ends a crease") != std::string::npos);
  CHECK(message.find("vertex") != std::string::npos);
}

TEST_CASE("dual crease: one non-manifold vertex elsewhere leaves the crease Chaikin's refinement, the vertex a gap") {
  // A triangle touching the creased torus at one vertex, away from the crease loop (j = 3),
  // makes that vertex non-manifold (two fans). The feature split skips it locally; before,
  // the whole level fell back to the plain split and lost every crease.
  CreasedTorus t = creased_torus();
  const Index pinch = 3 * 8 + 4;  // (i, j) = (4, 3)
  const Index a = t.mesh.vertex_count, b = a + 1;
  for (int k = 0; k < 2; ++k)
    for (int c = 0; c < 3; ++c) t.mesh.positions.push_back(t.mesh.positions[size_t(3 * pinch + c)] + (c == 2 ? 0.5 : 0.1 * (k + 1)));
  t.mesh.vertex_count += 2;
  t.mesh.add_face({pinch, a, b});
  const Level base = tagged(t.mesh, t.loop, true, 10.f);
  REQUIRE(base.non_manifold_vertex(pinch));
  const auto s = load_scheme("doo-sabin", {});
  RefineOptions options;
  options.levels = 3;
  const Hierarchy h = refine(*s, base, options);
  check_chaikin_crease_loop(h, t, 3);
}

TEST_CASE("dual crease: limit points next to a semi-sharp crease or corner are refused (they round off)") {
  const CreasedTorus t = creased_torus();
  std::string message;
  try {
    (void)select_limit(load_scheme_sequence("doo-sabin", 1, {}), tagged(t.mesh, t.loop, true, 2.5f));
  } catch (const Error& e) {
    message = e.what();
  }
  CHECK(message.find("semi-sharp") != std::string::npos);
  test::Mesh m = test::torus(8, 6);
  Level L = m.level();
  L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
  L.vertex_sharpness[10] = 1.5f;
  message.clear();
  try {
    (void)select_limit(load_scheme_sequence("doo-sabin", 1, {}), L);
  } catch (const Error& e) {
    message = e.what();
  }
  CHECK(message.find("semi-sharp") != std::string::npos);
}

TEST_CASE("dual corner: the corner point stays (its row is the corner alone) while its ring doubles every level") {
  // So a dual corner has no invariant neighbourhood and no stationary local subdivision
  // matrix: eigenvalue 1 with the corner's own eigenvector is all there is (docs/analysis.md).
  test::Mesh m = test::torus(8, 6);
  Level L = m.level();
  L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
  L.vertex_sharpness[10] = 10.f;
  RefineOptions options;
  options.levels = 3;
  const Hierarchy h = refine(*load_scheme("doo-sabin", {}), L, options);
  Index corner = 10;
  int valence = L.valence(corner);
  CHECK(valence == 4);
  for (int l = 0; l < 3; ++l) {
    const StencilTable& s = h.stencils[size_t(l)];
    Index child = kNone;
    for (Index c = 0; c + 1 < Index(s.offsets.size()); ++c)
      if (s.offsets[c + 1] - s.offsets[c] == 1 && s.indices[s.offsets[c]] == corner && s.weights[s.offsets[c]] == 1.0)
        child = c;
    REQUIRE(child != kNone);
    const int next = h.levels[size_t(l) + 1].valence(child);
    CHECK(next == 2 * valence);  // the F-faces of its faces and the E-faces of its edges
    corner = child, valence = next;
  }
}
