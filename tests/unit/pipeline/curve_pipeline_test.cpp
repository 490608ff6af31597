// The curve pipeline (framework/pipeline/curve_pipeline.h): polylines refined by a curve
// scheme with their point arrays. Checked against Chaikin's corner cutting written out here
// (Chaikin 1974, "An algorithm for high-speed curve generation": each edge ab gives
// 3/4 a + 1/4 b and 1/4 a + 3/4 b), against the positions themselves (an array holding x
// must refine as x does: the arrays and the points share one linear rule), and against
// projective invariance of rational weights (scaling them all changes nothing).
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "framework/pipeline/curve_pipeline.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"

namespace subdiv {
namespace {

// An open polyline, not straight, with uneven spacing.
MeshData zigzag() {
  MeshData m;
  m.positions = {0, 0, 0, 1, 0.2, 0, 2.5, 1, 0.3, 3, -1, 0, 4.2, 0.5, -0.4};
  m.line_vertices = {0, 1, 2, 3, 4};
  m.line_offsets = {0, 5};
  return m;
}

// A closed polygon: OBJ's "l 1 2 3 4 1".
MeshData square_polygon() {
  MeshData m;
  m.positions = {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1.5, 0};
  m.line_vertices = {0, 1, 2, 3, 0};
  m.line_offsets = {0, 5};
  return m;
}

CurveRefineRequest request(MeshData mesh, const std::string& scheme, int levels) {
  CurveRefineRequest r;
  r.mesh = std::move(mesh);
  r.mesh_name = "test polyline";
  r.scheme.text = scheme;
  r.levels = levels;
  return r;
}

// Chaikin's closed-polygon step, points as xyz.
std::vector<double> chaikin_closed(const std::vector<double>& p) {
  const size_t n = p.size() / 3;
  std::vector<double> out;
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    for (int c = 0; c < 3; ++c) out.push_back(0.75 * p[3 * i + c] + 0.25 * p[3 * j + c]);
    for (int c = 0; c < 3; ++c) out.push_back(0.25 * p[3 * i + c] + 0.75 * p[3 * j + c]);
  }
  return out;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double d = 0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

// The polygon's points in its own order (the level lists closed polygons once).
std::vector<double> polygon_points(const RefinedCurveLevel& level) {
  std::vector<double> out;
  for (Index v : level.topology.polyline(0))
    for (int c = 0; c < 3; ++c) out.push_back(level.mesh.positions[3 * size_t(v) + c]);
  return out;
}

TEST_CASE("a closed polygon refined by chaikin is Chaikin's corner cutting, level by level") {
  CurveRefineRequest r = request(square_polygon(), "chaikin", 4);
  const CurveRefineResult result = refine_curve_request(std::move(r));
  REQUIRE(result.levels.size() == 5);  // every level kept by default
  std::vector<double> expected = {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1.5, 0};
  for (int l = 1; l <= 4; ++l) {
    expected = chaikin_closed(expected);
    const RefinedCurveLevel& level = result.levels[size_t(l)];
    CHECK(level.level == l);
    CHECK(level.topology.is_closed(0));
    CHECK(level.topology.vertex_count == Index(4) << l);
    // The polygon may start at another point: find the first expected point in it.
    const std::vector<double> got = polygon_points(level);
    const size_t n = got.size() / 3;
    size_t shift = n;
    for (size_t s = 0; s < n && shift == n; ++s)
      if (std::abs(got[3 * s] - expected[0]) + std::abs(got[3 * s + 1] - expected[1]) < 1e-12) shift = s;
    REQUIRE(shift < n);
    std::vector<double> rotated;
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) rotated.push_back(got[3 * ((i + shift) % n) + c]);
    CHECK(max_difference(rotated, expected) < 1e-14);
  }
}

TEST_CASE("point arrays refine by the positions' own rule: an array holding x equals the refined x") {
  for (const std::string scheme : {"chaikin", "four-point", "cubic-bspline"}) {
    CAPTURE(scheme);
    MeshData m = zigzag();
    DataArray x{"x", 1, {}, false}, label{"label", 1, {}, true};
    for (Index v = 0; v < m.vertex_count(); ++v) x.values.push_back(m.positions[3 * size_t(v)]);
    for (Index v = 0; v < m.vertex_count(); ++v) label.values.push_back(double(v % 2));
    m.point_data = {x, label};
    CurveRefineRequest r = request(std::move(m), scheme, 3);
    r.keep_all_levels = false;
    const CurveRefineResult result = refine_curve_request(std::move(r));
    REQUIRE(result.levels.size() == 1);
    const RefinedCurveLevel& fine = result.levels.back();
    CHECK(fine.level == 3);
    REQUIRE(fine.mesh.point_data.size() == 2);
    const DataArray& carried = fine.mesh.point_data[0];
    REQUIRE(carried.values.size() == size_t(fine.topology.vertex_count));
    for (Index v = 0; v < fine.topology.vertex_count; ++v)
      CHECK(carried.values[size_t(v)] == doctest::Approx(fine.mesh.positions[3 * size_t(v)]).epsilon(1e-13));
    // Polylines have no element origins: an integer label is interpolated, so the
    // partition of unity gives values in [0, 1] that are not all 0 or 1.
    CHECK_FALSE(fine.mesh.point_data[1].integer);
    bool fractional = false;
    for (double value : fine.mesh.point_data[1].values) {
      CHECK(value >= -0.25);  // four-point overshoots a little: its weights are not all positive
      CHECK(value <= 1.25);
      fractional = fractional || (value > 1e-9 && value < 1 - 1e-9);
    }
    CHECK(fractional);
    CHECK(fine.rules.size() == size_t(fine.topology.vertex_count));
  }
}

TEST_CASE("rational weights: scaling every weight leaves the refined points unchanged; weights 1 are the plain curve") {
  auto refined = [](double scale, bool weighted) {
    MeshData m = square_polygon();
    if (weighted) m.point_data = {{"w", 1, {scale * 1.0, scale * 2.0, scale * 0.5, scale * 1.0}, false}};
    CurveRefineRequest r = request(std::move(m), "chaikin", 3);
    r.weights_array = weighted ? "w" : "";
    r.keep_all_levels = false;
    return refine_curve_request(std::move(r)).levels.back();
  };
  const RefinedCurveLevel a = refined(1, true), b = refined(7.5, true), plain = refined(1, false);
  CHECK(max_difference(a.mesh.positions, b.mesh.positions) < 1e-13);
  CHECK(max_difference(a.mesh.positions, plain.mesh.positions) > 1e-3);  // the weights move the curve
  // The refined weights are written as "weight" (OBJ's fourth coordinate).
  REQUIRE(a.mesh.point_data.size() == 1);
  CHECK(a.mesh.point_data[0].name == "weight");

  MeshData ones = square_polygon();
  ones.point_data = {{"weight", 1, {1, 1, 1, 1}, false}};
  CurveRefineRequest r = request(std::move(ones), "chaikin", 3);
  r.keep_all_levels = false;
  CHECK(refine_curve_request(std::move(r)).levels.back().mesh.positions == plain.mesh.positions);  // bit for bit
}

TEST_CASE("the finest level's description names each point's level and rule, each polyline and whether it is closed") {
  CurveRefineRequest r = request(zigzag(), "chaikin", 2);
  const CurveRefineResult result = refine_curve_request(std::move(r));
  const CurveLevelDescription d = describe_curve_level(result.levels.back());
  REQUIRE(d.point_data.size() == 2);
  CHECK(d.point_data[0].name == "rule");
  CHECK(d.point_data[1].name == "level");
  CHECK(d.point_data[1].values.front() == 2);
  REQUIRE(d.cell_data.size() == 2);
  CHECK(d.cell_data[0].values == std::vector<double>{0});
  CHECK(d.cell_data[1].values == std::vector<double>{0});  // open
}

TEST_CASE("what cannot be refined is refused with the place; the memory budget is honoured before any work") {
  MeshData faces;
  faces.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  faces.face_vertices = {0, 1, 2};
  faces.face_offsets = {0, 3};
  CHECK_THROWS_WITH_AS(refine_curve_request(request(faces, "chaikin", 1)), doctest::Contains("test polyline"), Error);
  CHECK_THROWS_AS(refine_curve_request(request(zigzag(), "catmull-clark", 1)), Error);

  CurveRefineRequest big = request(zigzag(), "chaikin", 20);
  big.memory_budget = 1 << 20;
  try {
    refine_curve_request(std::move(big));
    FAIL("a refinement past its budget was accepted");
  } catch (const OptionError& e) {
    CHECK(std::string(e.spelled({{"levels", "--levels"}})).find("--levels") != std::string::npos);
    CHECK(std::string(e.what()).find("GiB") != std::string::npos);
  }
}

}  // namespace
}  // namespace subdiv
