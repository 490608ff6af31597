// The linear C++ plugin (kobbelt-quad): its schemes produce stencil tables, so they get
// composition and the curve analysis like JSON schemes; its rule role works in JSON files.
#include <cmath>
#include <doctest/doctest.h>
#include <fstream>
#include <string>

#include "framework/analysis/curve/curve_analysis.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/scheme/scheme_validator.h"
#include "framework/util/error.h"
#include "support/cli_runner.h"
#include "support/refine_helpers.h"
#include "support/test_meshes.h"
#include "unit/plugins/plugin_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// A polynomial of bidegree (3, 3): the tensor-product four-point scheme reproduces it.
double cubic(double x, double y) { return 0.3 * x * x * x - x * x * y + 2 * x * y * y * y + 0.5 * y * y - x + 4; }

CurveMask mask_of(const CurveScheme& c) {
  std::vector<std::vector<double>> weights;
  for (const auto& rule : c.weights) {
    weights.emplace_back();
    for (const auto& w : rule) weights.back().push_back(std::stod(w));
  }
  return mask_from_rules(c.arity, c.starts, weights);
}

}  // namespace

TEST_CASE("kobbelt-quad (linear C++ rules) produces stencil tables: affine rows, interpolatory, composable") {
  load_example_plugins();
  const auto scheme = load_scheme("kobbelt-quad");
  CHECK(scheme->linear());
  CHECK(scheme->steps.front().code != nullptr);
  const Mesh g = grid(6, 5);
  RefineOptions options;
  options.levels = 2;
  const Hierarchy h = refine(*scheme, g.level(), options);
  CHECK(h.linear());
  REQUIRE(h.stencils.size() == 2);
  for (int l = 0; l < 2; ++l) {
    const StencilTable& t = h.stencils[l];
    CHECK(t.row_count() == h.levels[l + 1].vertex_count);
    CHECK(t.source_count == h.levels[l].vertex_count);
    for (Index r = 0; r < t.row_count(); ++r) {
      double sum = 0;
      for (Index i = t.offsets[r]; i < t.offsets[r + 1]; ++i) sum += t.weights[i];
      CHECK(sum == doctest::Approx(1.0).epsilon(1e-14));
    }
    // Interpolatory: the child of each old vertex is that vertex.
    for (Index v = 0; v < h.levels[l].vertex_count; ++v) {
      CHECK(t.row_size(v) == 1);
      CHECK(weight_of(t, v, v) == 1.0);
    }
  }
  // One composed table gives the same positions as the two steps.
  const auto stepwise = interpolate(h, 2, g.positions, 3);
  const auto composed = compose(h.stencils[0], h.stencils[1]).apply(g.positions, 3);
  REQUIRE(composed.size() == stepwise.size());
  for (size_t i = 0; i < composed.size(); ++i) CHECK(composed[i] == doctest::Approx(stepwise[i]).epsilon(1e-13));
}

TEST_CASE("kobbelt-quad reproduces bicubic polynomials away from the boundary") {
  load_example_plugins();
  Mesh g = grid(10, 10);
  for (size_t i = 0; i < g.positions.size(); i += 3) g.positions[i + 2] = cubic(g.positions[i], g.positions[i + 1]);
  const Refined r = refine_mesh(g, "kobbelt-quad", 1);
  int checked = 0;
  for (size_t i = 0; i < r.positions.size(); i += 3) {
    const double x = r.positions[i], y = r.positions[i + 1];
    if (x < 2 || x > 8 || y < 2 || y > 8) continue;  // the four-point stencils reach two cells out
    CHECK(r.positions[i + 2] == doctest::Approx(cubic(x, y)).epsilon(1e-12));
    ++checked;
  }
  CHECK(checked == 13 * 13);
  // The plain bilinear scheme does not (it only reproduces bilinear functions).
  const Refined b = refine_mesh(g, "bilinear", 1);
  double worst = 0;
  for (size_t i = 0; i < b.positions.size(); i += 3)
    worst = std::max(worst, std::abs(b.positions[i + 2] - cubic(b.positions[i], b.positions[i + 1])));
  CHECK(worst > 0.1);
}

TEST_CASE("dubuc-deslauriers: a linear curve scheme computed in C++, analysed like a JSON one") {
  load_example_plugins();
  const auto four = load_curve("dubuc-deslauriers");
  CHECK_FALSE(four->nonlinear);
  const CurveMask m2 = trimmed(mask_of(*four));
  // m = 2 is the four-point scheme with w = 1/16: mask (-1, 0, 9, 16, 9, 0, -1)/16.
  const double expected[] = {-1, 0, 9, 16, 9, 0, -1};
  REQUIRE(m2.coefficients.size() == 7);
  CHECK(m2.first == -3);
  for (int i = 0; i < 7; ++i) CHECK(m2.coefficients[i] == doctest::Approx(expected[i] / 16).epsilon(1e-15));
  const CurveAnalysis a2 = analyse_curve(m2);
  CHECK(a2.convergent);
  CHECK(a2.smoothness == 1);

  const auto six = load_curve("dubuc-deslauriers", {{"m", "3"}});
  const CurveMask m3 = trimmed(mask_of(*six));
  CHECK(m3.coefficients.size() == 11);  // the six-point scheme: (3, 0, -25, 0, 150, 256, 150, 0, -25, 0, 3)/256
  CHECK(m3.coefficients[0] == doctest::Approx(3.0 / 256).epsilon(1e-15));
  CHECK(m3.coefficients[4] == doctest::Approx(150.0 / 256).epsilon(1e-15));
  const CurveAnalysis a3 = analyse_curve(m3);
  CHECK(a3.convergent);
  CHECK(a3.smoothness >= 2);
  MESSAGE("dubuc-deslauriers m = 3: proven C", a3.smoothness);

  CHECK_THROWS_WITH_AS(load_curve("dubuc-deslauriers", {{"m", "2.5"}}), doctest::Contains("whole number"), Error);
  CHECK_THROWS_WITH_AS(load_curve("dubuc-deslauriers", {{"m", "20"}}), doctest::Contains("outside its range"), Error);
}

TEST_CASE("kobbelt-quad takes --param w and passes m on to its boundary curve") {
  load_example_plugins();
  const auto s = load_scheme("kobbelt-quad", {{"w", "0"}, {"m", "3"}});
  CHECK(s->parameter_values().at("w") == 0.0);
  CHECK(s->curve->name == "dubuc-deslauriers");
  CHECK(s->curve->weights[1].size() == 6);
  CHECK_THROWS_WITH_AS(load_scheme("kobbelt-quad", {{"beta", "1"}}), doctest::Contains("no parameter 'beta'"), Error);
  CHECK_THROWS_WITH_AS(load_scheme("kobbelt-quad", {{"w", "1"}}), doctest::Contains("outside its range"), Error);
  // w = 0: the edge and face points are plain midpoints and centroids (bilinear), on a
  // closed mesh (boundaries would follow the curve scheme, which w does not change).
  Mesh g = torus(8, 6);
  for (size_t i = 0; i < g.positions.size(); i += 3) g.positions[i + 2] += 0.3 * std::sin(double(i));
  const Refined k = refine_mesh(g, "kobbelt-quad", 1, {}, {{"w", "0"}});
  const Refined b = refine_mesh(g, "bilinear", 1);
  REQUIRE(k.positions.size() == b.positions.size());
  for (size_t i = 0; i < k.positions.size(); ++i) CHECK(k.positions[i] == doctest::Approx(b.positions[i]).epsilon(1e-14));
}

TEST_CASE("a JSON scheme file uses the plugin's role 'line'") {
  load_example_plugins();
  const auto dir = fresh_dir("plugin-role");
  const auto file = dir / "line-quad.json";
  std::ofstream(file) << R"({
  "name": "line-quad",
  "description": "test: four-point edge points along the plugin role 'line', centroid face points",
  "split": "quad",
  "curve": "four-point",
  "rules": {
    "vertex": [{"at": "self", "w": "1"}],
    "edge": [{"sum": "line", "w": "j == 0 || j == 3 ? -1/16 : 9/16"}],
    "face": [{"sum": "vertices", "w": "1/k"}]
  }
})";
  const auto scheme = load_scheme(file.string());
  const Mesh g = grid(6, 6);
  const Level level = g.level();
  RefineOptions options;
  options.levels = 1;
  const Hierarchy h = refine(*scheme, level, options);
  // The interior horizontal edge (3,3)-(4,3) reads (2,3), (3,3), (4,3), (5,3).
  auto id = [](int i, int j) { return Index(j * 7 + i); };
  const Index e = find_edge(level, id(3, 3), id(4, 3));
  REQUIRE(e != kNone);
  Index row = kNone;
  for (Index c = 0; c < Index(h.origins[0].kind.size()); ++c)
    if (h.origins[0].kind[c] == OriginKind::Edge && h.origins[0].parent[c] == e) row = c;
  REQUIRE(row != kNone);
  const StencilTable& t = h.stencils[0];
  CHECK(t.row_size(row) == 4);
  CHECK(weight_of(t, row, id(2, 3)) == doctest::Approx(-1.0 / 16));
  CHECK(weight_of(t, row, id(3, 3)) == doctest::Approx(9.0 / 16));
  CHECK(weight_of(t, row, id(4, 3)) == doctest::Approx(9.0 / 16));
  CHECK(weight_of(t, row, id(5, 3)) == doctest::Approx(-1.0 / 16));
  // `subdiv validate`'s sweep knows the role's size.
  const ValidationReport report = validate_scheme_file(file.string());
  const std::string first_error = report.errors.empty() ? std::string() : report.errors.front().message;
  CHECK_MESSAGE(report.ok(), first_error);
  // A role the element does not have is an error naming the plugin roles that exist.
  std::ofstream(dir / "bad.json") << R"({"name": "bad", "split": "quad", "rules": {
    "vertex": [{"sum": "line", "w": "1/4"}], "edge": [{"sum": "ends", "w": "1/2"}], "face": [{"sum": "vertices", "w": "1/k"}]}})";
  CHECK_THROWS_WITH_AS(load_scheme((dir / "bad.json").string()), doctest::Contains("role 'line' does not exist around a vertex"),
                       Error);
}

TEST_CASE("kobbelt-quad (rules in C++, no row plans) gives the same bits with and without stencil tables") {
  load_example_plugins();
  const auto scheme = load_scheme("kobbelt-quad");
  const Mesh g = grid(6, 5);
  RefineOptions options;
  options.levels = 2;
  const Hierarchy topology = refine_topology(*scheme, g.level(), options);
  const Hierarchy tables = refine(*scheme, g.level(), options);
  std::vector<double> direct = g.positions;
  for (int l = 0; l < 2; ++l) direct = step_values(*scheme, topology, l, direct, 3, options);
  CHECK(direct == interpolate(tables, 2, g.positions, 3));
}
