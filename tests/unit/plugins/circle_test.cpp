// The circle-preserving plugin (Sabin & Dodgson 2004): a non-linear curve scheme
// and a non-linear quad scheme, applied directly by the engine.
#include <cmath>
#include <doctest/doctest.h>
#include <vector>

#include "framework/plugin/polyline_refine.h"
#include "framework/engine/evaluator.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/test_meshes.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

const double kPi = std::acos(-1.0);

// A circle of radius 2 around c in the plane spanned by the orthonormal u, v.
struct Circle {
  double c[3] = {1.0, -0.5, 0.3};
  double u[3] = {0.6, 0.8, 0.0};
  double v[3] = {0.0, 0.0, 1.0};
  double r = 2.0;

  std::vector<double> points(const std::vector<double>& angles) const {
    std::vector<double> p;
    for (double t : angles)
      for (int d = 0; d < 3; ++d) p.push_back(c[d] + r * (std::cos(t) * u[d] + std::sin(t) * v[d]));
    return p;
  }
  // Largest distance of the points from the circle (radially and out of its plane).
  double error(const std::vector<double>& p) const {
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double worst = 0;
    for (size_t i = 0; i < p.size(); i += 3) {
      double q[3], off = 0;
      for (int d = 0; d < 3; ++d) q[d] = p[i + d] - c[d], off += q[d] * n[d];
      worst = std::max({worst, std::abs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] - off * off) - r), std::abs(off)});
    }
    return worst;
  }
};

}  // namespace

TEST_CASE("circle-four-point keeps points on the circle to 1e-12 at level 6; the linear four-point does not") {
  load_example_plugins();
  const Circle circle;
  // Unevenly spaced samples of the whole circle.
  const std::vector<double> angles{0.0, 0.7, 1.9, 2.4, 3.5, 4.1, 5.3};
  const auto points = circle.points(angles);
  const auto nonlinear = load_curve("circle-four-point");
  REQUIRE(nonlinear->nonlinear);
  const auto refined = refine_polyline(*nonlinear, points, 3, true, 6);
  CHECK(refined.size() == points.size() << 6);
  CHECK(circle.error(refined) < 1e-12);
  // Interpolatory: the input points are every 64th point.
  for (size_t i = 0; i < angles.size(); ++i)
    for (int d = 0; d < 3; ++d) CHECK(refined[64 * 3 * i + d] == doctest::Approx(points[3 * i + d]).epsilon(1e-15));

  const auto linear = load_curve("four-point");
  REQUIRE_FALSE(linear->nonlinear);
  const double linear_error = circle.error(refine_polyline(*linear, points, 3, true, 6));
  MESSAGE("distance from the circle at level 6: circle-preserving ", circle.error(refined), ", linear four-point ",
          linear_error);
  CHECK(linear_error > 1e-3);
}

TEST_CASE("circle-four-point: evenly spaced points get the arc midpoints; open arcs stay on the circle; lines stay lines") {
  load_example_plugins();
  const auto scheme = load_curve("circle-four-point");
  const Circle circle;
  std::vector<double> even;
  for (int i = 0; i < 6; ++i) even.push_back(2 * kPi * i / 6);
  const auto once = refine_polyline(*scheme, circle.points(even), 3, true, 1);
  std::vector<double> halves;
  for (int i = 0; i < 12; ++i) halves.push_back(2 * kPi * i / 12);
  const auto expected = circle.points(halves);
  for (size_t i = 0; i < expected.size(); ++i) CHECK(once[i] == doctest::Approx(expected[i]).epsilon(1e-13));

  // An open arc over 200 degrees: the end segments use their one circle, still the same.
  const auto arc = refine_polyline(*scheme, circle.points({0.0, 0.9, 1.5, 2.6, 3.5}), 3, false, 5);
  CHECK(arc.size() == 3 * (4 * 32 + 1));
  CHECK(circle.error(arc) < 1e-12);

  // Collinear points, unevenly spaced, in 2D: every new point stays on the line.
  const std::vector<double> line{0, 1, 1, 3, 1.5, 4, 4, 9};  // y = 2x + 1
  const auto straight = refine_polyline(*scheme, line, 2, false, 4);
  for (size_t i = 0; i < straight.size(); i += 2) CHECK(straight[i + 1] == doctest::Approx(2 * straight[i] + 1));
  CHECK_THROWS_AS(refine_polyline(*scheme, std::vector<double>{0, 0, 0, 0}, 4, false, 1), Error);  // 4D points
}

TEST_CASE("circle-quad is non-linear: no stencils, applied directly; a regularly sampled torus stays on the torus") {
  load_example_plugins();
  const double R = 3.0, r = 1.0;
  const Mesh torus12 = torus(12, 8, false, R, r);
  const auto scheme = load_scheme("circle-quad");
  CHECK_FALSE(scheme->linear());
  RefineOptions options;
  options.levels = 4;
  const Hierarchy h = refine(*scheme, torus12.level(), options);
  CHECK_FALSE(h.linear());
  REQUIRE(h.direct.size() == 4);
  CHECK(h.direct[0] != nullptr);
  CHECK(h.stencils[0].row_count() == 0);
  const auto positions = interpolate(h, 4, torus12.positions, 3);
  CHECK(positions.size() == 3 * size_t(12 * 8 * 256));
  double worst = 0;
  for (size_t i = 0; i < positions.size(); i += 3) worst = std::max(worst, torus_error(&positions[i], R, r));
  CHECK(worst < 1e-12);

  // Kobbelt's linear quad scheme, the same rule with second differences, leaves the torus.
  const Hierarchy lin = refine(*load_scheme("kobbelt-quad"), torus12.level(), options);
  const auto linear_positions = interpolate(lin, 4, torus12.positions, 3);
  double linear_worst = 0;
  for (size_t i = 0; i < linear_positions.size(); i += 3)
    linear_worst = std::max(linear_worst, torus_error(&linear_positions[i], R, r));
  MESSAGE("distance from the torus at level 4: circle-quad ", worst, ", kobbelt-quad ", linear_worst);
  CHECK(linear_worst > 1e-4);
}

TEST_CASE("circle-quad through an Evaluator (engine/evaluator.h): every frame as interpolate gives it") {
  load_example_plugins();
  const Mesh torus12 = torus(12, 8, false, 3.0, 1.0);
  const auto scheme = load_scheme("circle-quad");
  RefineOptions options;
  options.levels = 2;
  const Hierarchy h = refine(*scheme, torus12.level(), options);
  Evaluator evaluator(*scheme, h, options);
  for (double scale : {1.0, 2.5, 0.5}) {  // frames: the torus grows and shrinks
    CAPTURE(scale);
    std::vector<double> frame = torus12.positions;
    for (double& x : frame) x *= scale;
    CHECK(evaluator.evaluate(frame, 3) == interpolate(h, 2, frame, 3));
  }
}

TEST_CASE("circle-quad on an open planar grid: interpolatory, flat, boundaries refined along their lines") {
  load_example_plugins();
  Mesh g = grid(5, 4);
  for (size_t i = 0; i < g.positions.size(); i += 3) g.positions[i] += 0.1 * std::sin(double(i));  // uneven in x
  RefineOptions options;
  options.levels = 2;
  const Hierarchy h = refine(*load_scheme("circle-quad"), g.level(), options);
  const auto once = apply_step(h, 0, g.positions, 3);
  for (size_t i = 0; i < g.positions.size(); ++i) CHECK(once[i] == g.positions[i]);  // old vertices first, unchanged
  const auto twice = interpolate(h, 2, g.positions, 3);
  for (size_t i = 2; i < twice.size(); i += 3) CHECK(twice[i] == 0.0);
  // A channel count the rule does not handle is an error, not garbage.
  CHECK_THROWS_AS(apply_step(h, 0, std::vector<double>(size_t(g.vertex_count) * 4, 0.0), 4), Error);
}

TEST_CASE("a non-linear scheme cannot be a boundary curve: a JSON scheme naming it is refused") {
  load_example_plugins();
  const std::string text = R"({"name": "needs-linear-curve", "split": "quad", "curve": "circle-four-point",
    "rules": {"vertex": [{"at": "self", "w": "1"}], "edge": [{"sum": "ends", "w": "1/2"}],
              "face": [{"sum": "vertices", "w": "1/k"}]}})";
  CHECK_THROWS_WITH_AS(load_scheme_text(text, "inline.json"), doctest::Contains("is non-linear"), Error);
}
