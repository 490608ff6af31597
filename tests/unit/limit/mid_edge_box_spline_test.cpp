// Two mid-edge steps on a regular grid refine the four-direction quadratic box spline (the
// Zwart-Powell element; docs/limit.md, "Mid-edge schemes"), evaluated in closed form
// (four_direction_patch.h). Tested against mathematics: the closed form against the element's
// definition (a convolution, integrated exactly here), its partition of unity, linear and
// quadratic precision (the element's moments), its refinement equation with the mid-edge double
// step's weights, C1 but not C2 across its knot lines; on meshes, the closed form against the
// descent to face centres, second derivatives against central differences of the first, the
// stencils, quadratic precision through the whole evaluation, and where there are none.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/limit/face_domain.h"
#include "framework/limit/four_direction_patch.h"
#include "framework/limit/limit_surface.h"
#include "framework/limit/mid_edge_limit.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

using limit_test::bumped;
using limit_test::distance;

// The Courant hat, the box spline of (1, 0), (0, 1), (1, 1): 1 at (1, 1), 0 outside the hexagon
// (0, 0), (1, 0), (2, 1), (2, 2), (1, 2), (0, 1), linear on its six triangles.
double hat(double x, double y) { return std::max(0.0, std::min({x, y, 2 - x, 2 - y, 1 - x + y, 1 + x - y})); }

// The element from its definition (de Boor, Höllig & Riemenschneider 1993, "Box splines", I):
// M = integral over t in [0, 1] of the hat at x - t (1, -1), moved to be centred on 0 (the
// sum of its directions is (3, 1)). The integrand is linear between the t where the path
// crosses the hat's lines x = k, y = k, x - y = k, so the trapezoid rule on those pieces is exact.
double element(double x, double y) {
  const double X = x + 1.5, Y = y + 0.5;
  std::vector<double> t{0, 1};
  for (int k = -4; k <= 6; ++k)
    for (double c : {X - k, k - Y, (X - Y - k) / 2})
      if (c > 0 && c < 1) t.push_back(c);
  std::sort(t.begin(), t.end());
  double sum = 0;
  for (size_t i = 0; i + 1 < t.size(); ++i)
    sum += (t[i + 1] - t[i]) * (hat(X - t[i], Y + t[i]) + hat(X - t[i + 1], Y + t[i + 1])) / 2;
  return sum;
}

size_t at(int p, int q) { return size_t((q + 1) * 3 + (p + 1)); }

// A spline sum_k c(k) M(x - k) over the integers at (x, y), with its derivatives, through the
// quadrant rows: the quadrant of the nearest lattice point w read in the frame reflected so
// that (a, b) = 2 (|x - w_x|, |y - w_y|) (the element is symmetric under reflections).
struct Jet {
  double f = 0, fx = 0, fy = 0, fxx = 0, fxy = 0, fyy = 0;
};
template <class C>
Jet spline(const C& c, double x, double y) {
  const double wx = std::round(x), wy = std::round(y);
  const int sx = x < wx ? -1 : 1, sy = y < wy ? -1 : 1;
  const QuadrantRows r = four_direction_rows(2 * std::fabs(x - wx), 2 * std::fabs(y - wy));
  Jet j;
  for (int q = -1; q <= 1; ++q)
    for (int p = -1; p <= 1; ++p) {
      const double k = c(int(wx) + sx * p, int(wy) + sy * q);
      const size_t i = at(p, q);
      j.f += k * r.position[i];
      j.fx += k * 2 * sx * r.da[i];
      j.fy += k * 2 * sy * r.db[i];
      j.fxx += k * 4 * r.daa[i];
      j.fxy += k * 4 * sx * sy * r.dab[i];
      j.fyy += k * 4 * r.dbb[i];
    }
  return j;
}

// The element itself through the closed form: the spline of the unit coefficient at 0.
Jet closed_element(double x, double y) {
  return spline([](int i, int j) { return i == 0 && j == 0 ? 1.0 : 0.0; }, x, y);
}

// Meshes: a regular torus, and closed meshes with valence-3 vertices and triangles (sub-faces).
std::vector<test::Mesh> meshes() { return {bumped(test::torus(12, 12)), bumped(test::cube()), bumped(test::pyramid())}; }

// A random point of face f: a quad's (u, v), or a point of a random sub-face.
std::array<double, 2> random_uv(const Level& L, Index f, std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0, 1);
  const int n = L.face_size(f);
  if (n == 4) return {U(rng), U(rng)};
  const int j = int(rng() % unsigned(n)), columns = sub_face_columns(n);
  return {j % columns + 0.5 * U(rng), j / columns + 0.5 * U(rng)};
}

}  // namespace

TEST_CASE("four-direction box spline: the closed form is the element's definition, with its support") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  double worst = 0;
  for (int k = 0; k < 200; ++k) {
    const double a = U(rng), b = U(rng);
    const QuadrantRows r = four_direction_rows(a, b);
    // The quadrant (a/2, b/2) of the lattice point 0 meets the elements of the 3 x 3 points
    // around it and no others.
    for (int q = -2; q <= 2; ++q)
      for (int p = -2; p <= 2; ++p) {
        const bool inside = std::abs(p) <= 1 && std::abs(q) <= 1;
        worst = std::max(worst, std::fabs((inside ? r.position[at(p, q)] : 0.0) - element(a / 2 - p, b / 2 - q)));
      }
  }
  CHECK(worst < 1e-15);
  // The derivatives: pieces are quadratics, so central differences of the definition are exact
  // to rounding away from the knot lines.
  double d1 = 0, d2 = 0;
  const double h = 1e-4;
  for (int k = 0; k < 100; ++k) {
    const double x = 3 * U(rng) - 1.5, y = 3 * U(rng) - 1.5;
    const Jet j = closed_element(x, y);
    const double dx = (element(x + h, y) - element(x - h, y)) / (2 * h);
    const double dy = (element(x, y + h) - element(x, y - h)) / (2 * h);
    const double dxx = (element(x + h, y) - 2 * element(x, y) + element(x - h, y)) / (h * h);
    const double dyy = (element(x, y + h) - 2 * element(x, y) + element(x, y - h)) / (h * h);
    const double dxy =
        (element(x + h, y + h) - element(x + h, y - h) - element(x - h, y + h) + element(x - h, y - h)) / (4 * h * h);
    // Skip the points whose differences straddle a knot line (x, y = k + 1/2, x +- y = k).
    const auto near = [&](double s) { return std::fabs(s - std::round(s)) < 3 * h; };
    if (near(x + 0.5) || near(y + 0.5) || near(x + y) || near(x - y)) continue;
    d1 = std::max({d1, std::fabs(dx - j.fx), std::fabs(dy - j.fy)});
    d2 = std::max({d2, std::fabs(dxx - j.fxx), std::fabs(dxy - j.fxy), std::fabs(dyy - j.fyy)});
  }
  CHECK(d1 < 1e-11);
  CHECK(d2 < 1e-7);
}

TEST_CASE("four-direction box spline: partition of unity, linear precision, quadratic precision with its moments") {
  // The element is the distribution of a sum of four uniform variables along its directions,
  // so its second moments are sum xi xi^T / 12: 1/4 in x and in y, 0 in xy. Hence
  // sum_k M(x - k) = 1, sum_k k M(x - k) = x, sum_k k_x^2 M(x - k) = x^2 + 1/4,
  // sum_k k_x k_y M(x - k) = x y: all quadratics are reproduced (degree 2 = the number of
  // directions that can be removed, 4 - 2).
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> U(-3, 3);
  double worst = 0;
  for (int k = 0; k < 200; ++k) {
    const double x = U(rng), y = U(rng);
    const Jet one = spline([](int, int) { return 1.0; }, x, y);
    const Jet lx = spline([](int i, int) { return double(i); }, x, y);
    const Jet ly = spline([](int, int j) { return double(j); }, x, y);
    const Jet xx = spline([](int i, int) { return double(i * i); }, x, y);
    const Jet xy = spline([](int i, int j) { return double(i * j); }, x, y);
    const Jet yy = spline([](int, int j) { return double(j * j); }, x, y);
    const auto off = [](const Jet& j, const Jet& e) {
      return std::max({std::fabs(j.f - e.f), std::fabs(j.fx - e.fx), std::fabs(j.fy - e.fy), std::fabs(j.fxx - e.fxx),
                       std::fabs(j.fxy - e.fxy), std::fabs(j.fyy - e.fyy)});
    };
    worst = std::max({worst, off(one, {1, 0, 0, 0, 0, 0}), off(lx, {x, 1, 0, 0, 0, 0}), off(ly, {y, 0, 1, 0, 0, 0}),
                      off(xx, {x * x + 0.25, 2 * x, 0, 2, 0, 0}), off(xy, {x * y, y, x, 0, 1, 0}),
                      off(yy, {y * y + 0.25, 0, 2 * y, 0, 0, 2})});
  }
  CHECK(worst < 1e-13);
}

TEST_CASE("four-direction box spline: refined by the mid-edge double step; C1 across its knot lines, not C2") {
  // Two mid-edge steps put the point of corner (g, j), w + (e + f)/4, at w/2 + (w + e)/4 +
  // (w + f)/4: the element at 0 is 1/2 of the four new elements at (+-1/4, +-1/4) (where 0 is
  // the corner) and 1/4 of the eight at (+-3/4, +-1/4) and (+-1/4, +-3/4) (where 0 is the
  // corner's neighbour), the new elements being M(2 (x - centre)).
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> U(-2, 2);
  double refined = 0;
  for (int k = 0; k < 300; ++k) {
    const double x = U(rng), y = U(rng);
    double sum = 0;
    for (int sx : {-1, 1})
      for (int sy : {-1, 1}) {
        sum += 0.5 * closed_element(2 * x - sx * 0.5, 2 * y - sy * 0.5).f;
        sum += 0.25 * closed_element(2 * x - sx * 1.5, 2 * y - sy * 0.5).f;
        sum += 0.25 * closed_element(2 * x - sx * 0.5, 2 * y - sy * 1.5).f;
      }
    refined = std::max(refined, std::fabs(sum - closed_element(x, y).f));
  }
  CHECK(refined < 1e-15);
  // A spline with random coefficients across each kind of knot line: the value and first
  // derivatives agree from both sides (to the step times the second derivatives), the second
  // derivatives do not.
  std::vector<double> c(81);
  for (double& x : c) x = U(rng);
  const auto coefficient = [&](int i, int j) { return c[size_t((i + 4) * 9 + j + 4)]; };
  const double d = 1e-9;
  double c1 = 0, c2 = 1e9;
  for (int k = 0; k < 50; ++k) {
    const double s = 0.8 * U(rng) / 2;
    // A point on x = 1/2, y = 1/2, x = y, x + y = 1, and the normal across the line there.
    const std::array<std::array<double, 4>, 4> lines{
        {{0.5, s, 1, 0}, {s, 0.5, 0, 1}, {s, s, 1, -1}, {s, 1 - s, 1, 1}}};
    for (const auto& l : lines) {
      const Jet a = spline(coefficient, l[0] + d * l[2], l[1] + d * l[3]);
      const Jet b = spline(coefficient, l[0] - d * l[2], l[1] - d * l[3]);
      c1 = std::max({c1, std::fabs(a.f - b.f), std::fabs(a.fx - b.fx), std::fabs(a.fy - b.fy)});
      c2 = std::min(c2, std::fabs(a.fxx - b.fxx) + std::fabs(a.fxy - b.fxy) + std::fabs(a.fyy - b.fyy));
    }
  }
  CHECK(c1 < 1e-7);
  CHECK(c2 > 1e-3);
}

TEST_CASE("mid-edge: the box spline's closed form equals the descent to face centres, in a few steps") {
  const auto scheme = load_scheme("mid-edge");
  for (const test::Mesh& m : meshes()) {
    const Level L = m.level();
    SchemeLimits limits(*scheme);
    const MidEdgeLimit fast(*scheme, L, {}, limits), slow(*scheme, L, {}, limits, false);
    REQUIRE(fast.closed_form());
    REQUIRE(!slow.closed_form());
    std::mt19937 rng(21);
    double worst = 0, scale = 0;
    int fast_steps = 0, slow_steps = 0, points = 0;
    for (int k = 0; k < 24; ++k) {
      const Index f = Index(rng() % unsigned(L.face_count()));
      const auto uv = random_uv(L, f, rng);
      const char* why = nullptr;
      const auto p = base_face_point(L, f, uv[0], uv[1], false, &why);
      REQUIRE(p);
      std::vector<double> first;
      for (Index v : fast.reads(*p))
        for (size_t c = 0; c < 3; ++c) first.push_back(m.positions[size_t(3 * v) + c]);
      const LimitSample a = fast.evaluate(*p, first, 3, 1), b = slow.evaluate(*p, first, 3, 1);
      REQUIRE(a.has_derivatives);
      REQUIRE(b.has_derivatives);
      worst = std::max({worst, distance(a.position, b.position), distance(a.du, b.du), distance(a.dv, b.dv)});
      for (size_t c = 0; c < 3; ++c) scale = std::max({scale, std::fabs(b.du[c]), std::fabs(b.dv[c])});
      fast_steps += a.steps, slow_steps += b.steps, ++points;
    }
    CHECK(worst < 1e-12 * std::max(1.0, scale));
    // A random double descends about 53 double steps to a face's centre; the closed form ends
    // at once on the torus and within a few steps of the extraordinary points elsewhere.
    CHECK(slow_steps > 40 * points);
    CHECK(fast_steps <= 5 * points);
    if (L.face_count() == 144) CHECK(fast_steps == 0);
  }
}

TEST_CASE("mid-edge: second derivatives are central differences of the first, and the stencils' weights") {
  const auto scheme = load_scheme("mid-edge");
  for (const test::Mesh& m : meshes()) {
    const Level L = m.level();
    const LimitSurface s(scheme, L);
    std::mt19937 rng(22);
    const double h = 1e-5;
    double worst = 0, scale = 0, stencil = 0;
    for (int k = 0; k < 16; ++k) {
      const Index f = Index(rng() % unsigned(L.face_count()));
      const auto uv = random_uv(L, f, rng);
      const LimitSample p = s.evaluate(f, uv[0], uv[1], m.positions, 3, 2);
      REQUIRE(p.has_second_derivatives);
      const LimitSample a = s.evaluate(f, uv[0] + h, uv[1], m.positions, 3), b = s.evaluate(f, uv[0] - h, uv[1], m.positions, 3);
      const LimitSample c = s.evaluate(f, uv[0], uv[1] + h, m.positions, 3), d = s.evaluate(f, uv[0], uv[1] - h, m.positions, 3);
      for (size_t r = 0; r < 3; ++r) {
        worst = std::max({worst, std::fabs((a.du[r] - b.du[r]) / (2 * h) - p.duu[r]),
                          std::fabs((a.dv[r] - b.dv[r]) / (2 * h) - p.duv[r]),
                          std::fabs((c.du[r] - d.du[r]) / (2 * h) - p.duv[r]),
                          std::fabs((c.dv[r] - d.dv[r]) / (2 * h) - p.dvv[r])});
        scale = std::max({scale, std::fabs(p.duu[r]), std::fabs(p.duv[r]), std::fabs(p.dvv[r])});
      }
      const LimitStencil w = s.stencil(f, uv[0], uv[1], 2);
      REQUIRE(w.has_second_derivatives);
      std::array<double, 9> x{};
      for (size_t i = 0; i < w.vertices.size(); ++i)
        for (size_t c3 = 0; c3 < 3; ++c3) {
          const double P = m.positions[size_t(3 * w.vertices[i]) + c3];
          x[c3] += w.duu[i] * P, x[3 + c3] += w.duv[i] * P, x[6 + c3] += w.dvv[i] * P;
        }
      for (size_t c3 = 0; c3 < 3; ++c3)
        stencil = std::max({stencil, std::fabs(x[c3] - p.duu[c3]), std::fabs(x[3 + c3] - p.duv[c3]),
                            std::fabs(x[6 + c3] - p.dvv[c3])});
    }
    // Inside a piece the limit is a quadratic: the differences are exact to rounding.
    CHECK(worst < 1e-7 * std::max(1.0, scale));
    CHECK(stencil < 1e-12 * std::max(1.0, scale));
  }
}

TEST_CASE("mid-edge: quadratic precision through the evaluation, in every quadrant's frame") {
  // Control points (i, j, z(i, j)) on the grid with z a quadratic: the limit's z is z(u, v)
  // plus the element's second moments (1/4 per square), with z's second derivatives exactly.
  const int n = 16;
  test::Mesh m = limit_test::unrolled_torus(n);
  const auto z = [](double x, double y) { return 0.3 * x * x - 0.7 * x * y + 0.2 * y * y + x; };
  for (Index v = 0; v < m.vertex_count; ++v) m.positions[size_t(3 * v + 2)] = z(m.positions[size_t(3 * v)], m.positions[size_t(3 * v + 1)]);
  const LimitSurface s(load_scheme("mid-edge"), m.level());
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> U(0, 1);
  double worst = 0;
  for (int k = 0; k < 16; ++k) {
    const int i = 7 + k % 2, j = 7 + (k / 2) % 2;
    const double u = U(rng), v = U(rng), x = i + u, y = j + v;
    const LimitSample p = s.evaluate(Index(j * n + i), u, v, m.positions, 3, 2);
    REQUIRE(p.has_second_derivatives);
    worst = std::max({worst, std::fabs(p.position[2] - (z(x, y) + 0.25 * (0.3 + 0.2))),
                      std::fabs(p.du[2] - (0.6 * x - 0.7 * y + 1)), std::fabs(p.dv[2] - (-0.7 * x + 0.4 * y)),
                      std::fabs(p.duu[2] - 0.6), std::fabs(p.duv[2] + 0.7), std::fabs(p.dvv[2] - 0.4)});
    worst = std::max({worst, distance(p.duu, std::array<double, 3>{0, 0, 0.6}),
                      distance(p.dvv, std::array<double, 3>{0, 0, 0.4})});
  }
  CHECK(worst < 1e-12);
}

TEST_CASE("mid-edge: no second derivatives exactly on the knot lines and at extraordinary points") {
  const auto scheme = load_scheme("mid-edge");
  {
    // On a regular torus the closed form holds on every base face at once: its knot lines are
    // u = 1/2, v = 1/2, u = v, u + v = 1; the face's edges are not knot lines.
    const test::Mesh m = bumped(test::torus(12, 12));
    const LimitSurface s(scheme, m.level());
    std::mt19937 rng(24);
    std::uniform_real_distribution<double> U(0, 1);
    for (int k = 0; k < 8; ++k) {
      const Index f = Index(rng() % 144u);
      const double t = U(rng), w = std::max(t, 1 - t);  // 1 - w exact (w >= 1/2): w + (1 - w) = 1
      for (const auto& uv : {std::array{0.5, t}, std::array{t, 0.5}, std::array{t, t}, std::array{w, 1 - w},
                             std::array{0.0, 0.0}, std::array{0.5, 0.0}, std::array{0.5, 0.5}}) {
        const LimitSample p = s.evaluate(f, uv[0], uv[1], m.positions, 3, 2);
        CHECK(p.has_derivatives);
        CHECK(!p.has_second_derivatives);
        CHECK(p.duu.empty());
      }
      // Off them: numbers, on the face's edges too.
      const double off = t == 0.5 ? 0.3 : t;
      for (const auto& uv : {std::array{off, 0.0}, std::array{0.0, off}, std::array{off / 2, off / 3 + 0.6}}) {
        const LimitSample p = s.evaluate(f, uv[0], uv[1], m.positions, 3, 2);
        CHECK(p.has_second_derivatives);
        CHECK(std::isfinite(p.duu[0]));
      }
    }
  }
  for (const test::Mesh& m : {bumped(test::cube()), bumped(test::pyramid())}) {
    // A base vertex of valence other than 4 and the centre of a face that is not a quad are
    // extraordinary points: no derivatives at all; a quad's centre is where knot lines cross.
    const Level L = m.level();
    const LimitSurface s(scheme, L);
    for (Index f = 0; f < L.face_count(); ++f) {
      const int n = L.face_size(f);
      const LimitSample centre = s.evaluate(f, 0.5, 0.5, m.positions, 3, 2);  // an n-gon's too (sub-face 0's (1, 1))
      CHECK(centre.has_derivatives == (n == 4));
      CHECK(!centre.has_second_derivatives);
      const LimitSample corner = s.evaluate(f, 0, 0, m.positions, 3, 2);
      CHECK(corner.has_derivatives == (L.incident_face_count(L.face(f)[0]) == 4));
      CHECK(!corner.has_second_derivatives);
    }
  }
}

TEST_CASE("mid-edge: the closed form is chosen from the double step's rows, not the scheme's name") {
  // The same rule under another name and spelling takes the closed form; a mid-edge split
  // followed by a smoothing pass (its double step is not the box spline's refinement) keeps the
  // descent to face centres: positions and first derivatives, no second ones.
  const auto renamed = load_scheme_text(R"json({"name": "middles", "split": "mid-edge", "faces": "any",
    "rules": {"edge": [{"sum": "end-ring-0", "w": "j == 0 ? 1/2 : 0"}, {"sum": "end-ring-1", "w": "j == 0 ? 1/2 : 0"}]}})json",
                                        "middles.json");
  const auto smoothed = load_scheme_text(R"json({"name": "mid-edge-smoothed", "faces": "any", "steps": [
    {"split": "mid-edge", "rules": {"edge": [{"sum": "ends", "w": "1/2"}]}},
    {"smooth": {"vertex": [{"at": "self", "w": "1/2"}, {"sum": "ring", "w": "1/(2*n)"}]}}]})json",
                                         "smoothed.json");
  const test::Mesh m = bumped(test::cube());
  const Level L = m.level();
  SchemeLimits a(*renamed), b(*smoothed);
  CHECK(MidEdgeLimit(*renamed, L, {}, a).closed_form());
  CHECK(!MidEdgeLimit(*smoothed, L, {}, b).closed_form());
  const LimitSurface s(smoothed, L);
  const LimitSample p = s.evaluate(0, 0.3, 0.15, m.positions, 3, 2);
  CHECK(p.has_derivatives);
  CHECK(!p.has_second_derivatives);
  CHECK(p.steps > 40);
}
