// Point counts per level for closed and open polylines, arity 2 and 3, the end treatments,
// shared end points, and composition of the level tables.
#include <doctest/doctest.h>

#include <cmath>

#include "curve_test_support.h"
#include "framework/curve/curve_level.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

std::vector<long> counts(const CurveScheme& scheme, int n, bool closed, int levels) {
  const CurveHierarchy h = refine_curves(scheme, single_polyline(n, closed), levels);
  std::vector<long> out;
  for (const auto& level : h.levels) out.push_back(level.size(0));
  return out;
}

}  // namespace

TEST_CASE("closed polygons: N m^l points at level l, for arity 2 and 3") {
  for (const char* name : {"chaikin", "cubic-bspline", "four-point", "six-point", "tension-bspline", "two-point"})
    CHECK(counts(*load_curve(name), 5, true, 4) == std::vector<long>{5, 10, 20, 40, 80});
  for (const char* name : {"ternary-four-point", "ternary-bspline"})
    CHECK(counts(*load_curve(name), 5, true, 4) == std::vector<long>{5, 15, 45, 135, 405});
}

TEST_CASE("open polylines, ends interpolate: primal m(N-1)+1, dual (Chaikin) 2N with the end points added") {
  for (const char* name : {"cubic-bspline", "four-point", "six-point", "tension-bspline", "two-point"})
    CHECK(counts(*load_curve(name), 5, false, 4) == std::vector<long>{5, 9, 17, 33, 65});
  for (const char* name : {"ternary-four-point", "ternary-bspline"})
    CHECK(counts(*load_curve(name), 5, false, 3) == std::vector<long>{5, 13, 37, 109});
  CHECK(counts(*load_curve("chaikin"), 5, false, 4) == std::vector<long>{5, 10, 20, 40, 80});
  CHECK(counts(*load_curve("bspline", {{"d", "4"}}), 5, false, 3) == std::vector<long>{5, 10, 20, 40});
  // Even two points refine (missing neighbours are extrapolated linearly).
  CHECK(counts(*load_curve("six-point"), 2, false, 3) == std::vector<long>{2, 3, 5, 9});
}

TEST_CASE("open polylines, ends uniform: only points whose rule lies inside; the polygon shrinks to the spline's span") {
  // Cubic B-spline: N -> 2N - 3 (even rule on i = 1..N-2, odd rule on i = 0..N-2).
  const CurveScheme cubic = with_ends(*load_curve("cubic-bspline"), CurveEnds::Uniform);
  CHECK(counts(cubic, 6, false, 3) == std::vector<long>{6, 9, 15, 27});
  // Chaikin: N -> 2N - 2.
  CHECK(counts(with_ends(*load_curve("chaikin"), CurveEnds::Uniform), 6, false, 3) == std::vector<long>{6, 10, 18, 34});
  // Too short to keep two points: a clear error.
  CHECK_THROWS_WITH_AS(refine_curves(cubic, single_polyline(2, false), 1), doctest::Contains("too short"), Error);
}

TEST_CASE("closed polygons of interpolating schemes are closed loops: no seam at the first point") {
  // Rotating the input's numbering rotates the output: the first point is not special.
  const auto p = wiggly_points(6);
  std::vector<double> rotated(p.begin() + 6, p.end());
  rotated.insert(rotated.end(), p.begin(), p.begin() + 6);  // start at old point 2
  const auto scheme = load_curve("six-point");
  const RefinedCurve a = refine_polyline(*scheme, p, true, 3), b = refine_polyline(*scheme, rotated, true, 3);
  const long count = long(a.positions[3].size() / 3), shift = 2 * 8;  // old point 2 is new point 16 at level 3
  for (long c = 0; c < count; ++c)
    CHECK(distance(point(a.positions[3], (c + shift) % count), point(b.positions[3], c)) <= 1e-14);
}

TEST_CASE("levels compose: one table from level 0 to level 4 gives the same points") {
  const auto scheme = load_curve("tension-bspline", {{"alpha0", "0.3"}});
  const auto p = wiggly_points(7);
  for (bool closed : {true, false}) {
    const RefinedCurve r = refine_polyline(*scheme, p, closed, 4);
    StencilTable all = r.hierarchy.stencils[0];
    for (int l = 1; l < 4; ++l) all = compose(all, r.hierarchy.stencils[l]);
    const auto direct = all.apply(p, 3);
    REQUIRE(direct.size() == r.positions[4].size());
    for (size_t i = 0; i < direct.size(); ++i) CHECK(direct[i] == doctest::Approx(r.positions[4][i]).epsilon(1e-13));
    // Every row is an affine combination.
    for (Index row = 0; row < all.row_count(); ++row) {
      double sum = 0;
      for (Index k = all.offsets[row]; k < all.offsets[row + 1]; ++k) sum += all.weights[k];
      CHECK(sum == doctest::Approx(1.0).epsilon(1e-13));
    }
  }
}

TEST_CASE("polylines that end at the same vertex share the refined end point; a closed polygon stays closed") {
  MeshData mesh;
  mesh.positions = wiggly_points(9);
  mesh.line_vertices = {0, 1, 2, 3, /**/ 3, 4, 5, /**/ 6, 7, 8, 6};
  mesh.line_offsets = {0, 4, 7, 11};
  const CurveLevel base = curve_level_from_mesh(mesh, "strokes");
  REQUIRE(base.polyline_count() == 3);
  CHECK(base.closed == std::vector<std::uint8_t>{0, 0, 1});
  CHECK(base.size(2) == 3);
  const CurveHierarchy h = refine_curves(*load_curve("chaikin"), base, 2);
  const CurveLevel& fine = h.levels[2];
  CHECK(fine.size(0) == 16);
  CHECK(fine.size(1) == 12);
  CHECK(fine.size(2) == 12);
  CHECK(fine.vertex_count == 16 + 12 - 1 + 12);  // the joint is one point
  CHECK(fine.polyline(0).back() == fine.polyline(1).front());
  const MeshData out = mesh_from_curve_level(fine, std::vector<double>(size_t(fine.vertex_count) * 3, 0.0));
  CHECK(out.line_vertices[out.line_offsets[3] - 1] == out.line_vertices[out.line_offsets[2]]);  // l ... first
}

TEST_CASE("explicit end rules: the e-th point from each end, mirrored") {
  // Four-point with a cubic-exact end rule: the first new point is the cubic through the
  // first four points at 1/2, (5, 15, -5, 1)/16.
  const auto file = write_temp_scheme("four-point-cubic-ends", R"({
    "name": "four-point-cubic-ends", "kind": "curve", "arity": 2,
    "rules": [{"start": 0, "w": ["1"]}, {"start": -1, "w": ["-1/16", "9/16", "9/16", "-1/16"]}],
    "ends": {"rules": [{"w": ["1"]}, {"w": ["5/16", "15/16", "-5/16", "1/16"]}]}
  })");
  const auto scheme = load_curve(file.string());
  REQUIRE(scheme->ends == CurveEnds::Rules);
  auto cubic = [](double t) { return Vec3{t, 0.5 * t * t - t, 0.1 * t * t * t - 0.3 * t}; };
  std::vector<double> p;
  for (int i = 0; i < 6; ++i) {
    const Vec3 q = cubic(i);
    p.insert(p.end(), q.begin(), q.end());
  }
  // With cubic-exact ends the whole refined polygon lies on the cubic, ends included.
  const RefinedCurve r = refine_polyline(*scheme, p, false, 4);
  const auto& fine = r.positions[4];
  REQUIRE(long(fine.size() / 3) == 16 * 5 + 1);
  for (long c = 0; c < long(fine.size() / 3); ++c) CHECK(distance(point(fine, c), cubic(c / 16.0)) <= 1e-12);
  // Origins record the end rules.
  const CurveOrigins& o = r.hierarchy.origins[0];
  CHECK(o.rule.front() == -1);
  CHECK(o.rule[1] == -2);
  CHECK(o.rule.back() == -1);
  CHECK(o.rule[o.rule.size() - 2] == -2);
  CHECK(o.index.back() == 1);
  // A polyline too short for the end rules is refused.
  CHECK_THROWS_WITH_AS(refine_curves(*scheme, single_polyline(3, false), 1), doctest::Contains("end rule"), Error);
}
