// A scheme a student got wrong in a way `subdiv validate` cannot see: affine, symmetric and
// convergent, but not C1 on regular quads. Its limit has no derivatives, so asking for them is
// refused; positions are still evaluated. A scheme with other rules that is C1 there keeps its
// derivatives (checked against difference quotients of its own limit positions).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <string>

#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

// Catmull-Clark's face and edge rules with the vertex rule `vertex` (its three weights: the
// vertex, each ring neighbour, each new face point).
std::shared_ptr<const Scheme> quad_scheme(const std::string& name, const std::string& edge_ends,
                                          const std::string& edge_faces, const std::string vertex[3]) {
  const std::string text = R"({"name": ")" + name + R"(", "split": "quad", "faces": "any", "curve": "cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": ")" + edge_ends + R"("}, {"sum": "faces", "new": "face", "w": ")" +
                           edge_faces + R"("}],
              "vertex": [{"at": "self", "w": ")" + vertex[0] + R"("}, {"sum": "ring", "w": ")" + vertex[1] +
                           R"("}, {"sum": "faces", "new": "face", "w": ")" + vertex[2] + R"("}]}})";
  return load_scheme_text(text, name + ".json");
}

std::array<double, 3> position(const LimitSurface& s, const std::vector<double>& p, double u, double v) {
  const LimitSample x = s.evaluate(0, u, v, p, 3, 0);
  return {x.position[0], x.position[1], x.position[2]};
}

}  // namespace

TEST_CASE("a scheme that is not C1 at regular vertices: derivatives refused with the reason, positions evaluated") {
  // Vertex rule 0.9 v + 0.05/n (ring) + 0.05/n (face points): at valence 4 the subdominant
  // eigenvalues are 0.569 and 0.5 (`subdiv analyze`), not the 1/2 twice of a surface
  // differentiable in the halving parameters.
  const std::string vertex[3] = {"0.9", "0.05/n", "0.05/n"};
  const auto scheme = quad_scheme("stiff-vertices", "1/4", "1/4", vertex);
  const test::Mesh torus = test::torus(8, 8);  // every vertex regular
  const LimitSurface surface(scheme, torus.level());
  const std::vector<double>& P = torus.positions;
  // The difference quotients at the face's centre (a vertex after one step) grow without bound.
  const auto c = position(surface, P, 0.5, 0.5);
  double largest_coarse = 0, largest_fine = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const auto a = position(surface, P, 0.5 + std::ldexp(1.0, -8), 0.5);
    const auto b = position(surface, P, 0.5 + std::ldexp(1.0, -28), 0.5);
    largest_coarse = std::max(largest_coarse, std::fabs(a[size_t(axis)] - c[size_t(axis)]) * std::ldexp(1.0, 8));
    largest_fine = std::max(largest_fine, std::fabs(b[size_t(axis)] - c[size_t(axis)]) * std::ldexp(1.0, 28));
  }
  CHECK(largest_fine > 2 * largest_coarse);
  for (double u : {0.5, 0.3, 0.0}) {
    CAPTURE(u);
    CHECK_THROWS_WITH_AS(surface.evaluate(0, u, 0.5, P, 3, 1),
                         doctest::Contains("is not C1, so its limit has no derivatives"), Error);
    CHECK_THROWS_WITH_AS(surface.evaluate(0, u, 0.5, P, 3, 1), doctest::Contains("--derivatives 0"), Error);
    CHECK_THROWS_WITH_AS(surface.evaluate(0, u, 0.5, P, 3, 1), doctest::Contains("stiff-vertices.json"), Error);
  }
}

TEST_CASE("a scheme with other weights that is C1 at regular vertices keeps its derivatives") {
  // Edge points 1/8 (ends) + 3/8 (face points): eigenvalues 1/2, 1/2 at valence 4, C1.
  const std::string vertex[3] = {"(n-2)/n", "1/n^2", "1/n^2"};
  const auto scheme = quad_scheme("heavy-faces", "1/8", "3/8", vertex);
  const test::Mesh torus = test::torus(8, 8);
  const LimitSurface surface(scheme, torus.level());
  const std::vector<double>& P = torus.positions;
  const double h = std::ldexp(1.0, -12);
  for (double u : {0.5, 0.3}) {
    CAPTURE(u);
    const LimitSample s = surface.evaluate(0, u, 0.5, P, 3, 1);
    REQUIRE(s.has_derivatives);
    const auto a = position(surface, P, u + h, 0.5), b = position(surface, P, u - h, 0.5);
    for (int axis = 0; axis < 3; ++axis)
      CHECK(s.du[size_t(axis)] == doctest::Approx((a[size_t(axis)] - b[size_t(axis)]) / (2 * h)).epsilon(1e-3));
  }
}

namespace {

// Kobbelt's √3 (schemes/sqrt3.json) with the vertex rule `self` v + `ring` (each neighbour).
std::shared_ptr<const Scheme> sqrt3_scheme(const std::string& name, const std::string& self, const std::string& ring) {
  const std::string text = R"({"name": ")" + name + R"(", "split": "sqrt3", "faces": "triangles",
    "curve": "ternary-cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/3"}],
              "vertex": [{"at": "self", "w": ")" + self + R"("}, {"sum": "ring", "w": ")" + ring + R"("}]}})";
  return load_scheme_text(text, name + ".json");
}

}  // namespace

TEST_CASE("a √3 scheme that is not C1 at regular vertices: derivatives refused, positions evaluated") {
  // Keeping 0.95 of the vertex (alpha = 0.05): at valence 6 the double step's radial
  // eigenvalue (2/3 - alpha)^2 = 0.380 overtakes the 1/3 by which two √3 steps shrink the
  // parameters (Kobbelt 2000, sqrt(3)-subdivision, section 3; `subdiv analyze`: 0.380278,
  // 0.333333), so the difference quotients at a vertex do not settle.
  const auto scheme = sqrt3_scheme("stiff-sqrt3", "0.95", "0.05/n");
  const test::Mesh torus = test::torus(9, 9, true);  // every vertex of valence 6
  const LimitSurface surface(scheme, torus.level());
  const std::vector<double>& P = torus.positions;
  // The difference quotients at the face's centre (the vertex its first step adds) along u,
  // at h = 3^-4, 3^-16, 3^-28: where the limit is differentiable they settle, each change
  // O(h) smaller than the last; here the radial mode adds c h^(log 0.380 / log(1/3) - 1) =
  // c h^-0.12, so the later change (3^3.4 - 3^1.9) is the larger.
  const double u = 1.0 / 3, v = 1.0 / 3;
  const auto c = position(surface, P, u, v);
  auto quotient = [&](int k) {
    const double h = std::pow(3.0, -k);
    const auto a = position(surface, P, u + h, v);
    return std::array<double, 3>{(a[0] - c[0]) / h, (a[1] - c[1]) / h, (a[2] - c[2]) / h};
  };
  const auto q4 = quotient(4), q16 = quotient(16), q28 = quotient(28);
  double first = 0, second = 0;
  for (size_t axis = 0; axis < 3; ++axis) {
    first = std::max(first, std::fabs(q16[axis] - q4[axis]));
    second = std::max(second, std::fabs(q28[axis] - q16[axis]));
  }
  CAPTURE(first);
  CAPTURE(second);
  CHECK(second > first);  // no derivative
  for (double s : {1.0 / 3, 0.2, 0.0}) {
    CAPTURE(s);
    CHECK_THROWS_WITH_AS(surface.evaluate(0, s, 1.0 / 3, P, 3, 1),
                         doctest::Contains("scheme 'stiff-sqrt3' is not C1, so its limit has no derivatives"), Error);
    CHECK_THROWS_WITH_AS(surface.evaluate(0, s, 1.0 / 3, P, 3, 1), doctest::Contains("needs 0.333333"), Error);
    CHECK(std::isfinite(surface.evaluate(0, s, 1.0 / 3, P, 3, 0).position[0]));
  }
}

TEST_CASE("the shipped √3 schemes keep their derivatives (checked against central differences)") {
  const test::Mesh torus = test::torus(9, 9, true);
  const std::vector<double>& P = torus.positions;
  const double h = std::pow(3.0, -9);
  for (const char* name : {"sqrt3", "interpolating-sqrt3"}) {
    CAPTURE(name);
    const LimitSurface surface(load_scheme(name), torus.level());
    const LimitSample s = surface.evaluate(0, 0.3, 0.2, P, 3, 1);
    REQUIRE(s.has_derivatives);
    const auto a = position(surface, P, 0.3 + h, 0.2), b = position(surface, P, 0.3 - h, 0.2);
    for (int axis = 0; axis < 3; ++axis)
      CHECK(s.du[size_t(axis)] == doctest::Approx((a[size_t(axis)] - b[size_t(axis)]) / (2 * h)).epsilon(1e-3));
  }
}
