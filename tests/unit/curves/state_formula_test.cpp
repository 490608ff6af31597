// The formula additions: level-dependent state (any scheme, surface ones too) and the
// functions binom, floor, ceil, mod.
#include <doctest/doctest.h>

#include <cmath>

#include "curve_test_support.h"
#include "framework/rules/formula.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

NamedFormula state(const std::string& name, const std::string& initial, const std::string& next) {
  return {name, initial, "test.state." + name, next, "test.state." + name + ".next"};
}
NamedFormula definition(const std::string& name, const std::string& expression) {
  return {name, expression, "test.definitions." + name, "", ""};
}

double eval(FormulaSet& f, const std::string& expression, FormulaInputs in = {}) {
  return f.evaluate(f.add(expression, "test"), in);
}

}  // namespace

TEST_CASE("binom, floor, ceil and mod") {
  FormulaSet f({}, {});
  CHECK(eval(f, "binom(5, 2)") == 10);
  CHECK(eval(f, "binom(10, 0)") == 1);
  CHECK(eval(f, "binom(4, 5)") == 0);
  CHECK(eval(f, "binom(4, -1)") == 0);
  CHECK(eval(f, "binom(60, 30)") == 118264581564861424.0);
  CHECK(eval(f, "binom(-1/2, 2)") == doctest::Approx(0.375));  // generalised: (-1/2)(-3/2)/2
  CHECK(std::isnan(eval(f, "binom(4, 1.5)")));
  CHECK(eval(f, "floor(-2.5)") == -3);
  CHECK(eval(f, "ceil(-2.5)") == -2);
  CHECK(eval(f, "mod(-7, 3)") == 2);
  CHECK(eval(f, "mod(7, 3)") == 1);
  CHECK(binomial_coefficient(7, 3) == 35);
}

TEST_CASE("state: the value at level l is the recurrence applied l times; all variables update together") {
  // Fibonacci: a(l) = F_l, b(l) = F_{l+1}.
  FormulaSet f({{"scale", 2.0}}, {state("a", "0", "b"), state("b", "1", "a + b"), definition("twice", "scale * a")});
  const int id = f.add("twice + j", "test");
  CHECK(f.uses(id).l);  // through the state variable
  CHECK_FALSE(f.uses(id).n);
  const double fibonacci[] = {0, 1, 1, 2, 3, 5, 8, 13, 21, 34, 55, 89};
  for (int l = 10; l >= 0; --l) {  // any order: values are cached per level
    CAPTURE(l);
    CHECK(f.evaluate(id, {0, 0, 1, double(l)}) == 2 * fibonacci[l] + 1);
    CHECK(f.state_values(l) == std::vector<double>{fibonacci[l], fibonacci[l + 1]});
  }
  // The tension recurrence of Morin, Warren & Weimer 2001: alpha_k = sqrt((1 + alpha_{k-1})/2), from cos(theta).
  FormulaSet t({{"alpha0", std::cos(1.0)}}, {state("alpha", "sqrt((1 + alpha0)/2)", "sqrt((1 + alpha)/2)")});
  for (int l = 0; l < 10; ++l) CHECK(t.state_values(l)[0] == doctest::Approx(std::cos(1.0 / std::pow(2.0, l + 1))));
  // The recurrence sees l.
  FormulaSet counter({}, {state("x", "0", "x + l")});
  CHECK(counter.state_values(4)[0] == 0 + 0 + 1 + 2 + 3);
}

TEST_CASE("state errors: dependence on n, k or j, non-finite values, order, fractional levels") {
  CHECK_THROWS_WITH_AS(FormulaSet({}, {state("x", "j", "x")}), doctest::Contains("depends on j"), Error);
  CHECK_THROWS_WITH_AS(FormulaSet({}, {state("x", "1", "x * n")}), doctest::Contains("depends on n"), Error);
  CHECK_THROWS_WITH_AS(FormulaSet({}, {state("x", "1", "x +")}), doctest::Contains("does not parse"), Error);
  CHECK_THROWS_WITH_AS(FormulaSet({}, {definition("d", "1"), state("x", "1", "x")}), doctest::Contains("state must come first"),
                       Error);
  FormulaSet f({}, {state("x", "1", "sqrt(x - 2)")});
  const int id = f.add("x", "test");
  CHECK(f.evaluate(id, {0, 0, 0, 0}) == 1);
  CHECK_THROWS_WITH_AS(f.evaluate(id, {0, 0, 0, 1}), doctest::Contains("state variable 'x' is"), Error);
  CHECK_THROWS_WITH_AS(f.evaluate(id, {0, 0, 0, 0.5}), doctest::Contains("whole levels"), Error);
}

TEST_CASE("state in a surface scheme: a Loop variant whose edge weights change per level") {
  // Edge rule (1/2 - s, 1/2 - s, s, s) with s = 1/8, 1/16, ...: Loop's rule at level 0.
  const char* vertex_rule = R"([{"at": "self", "w": "1 - n*beta_n"}, {"sum": "ring", "w": "beta_n"}])";
  const auto file = write_temp_scheme("loop-with-state", std::string(R"({
    "name": "loop-with-state", "split": "triangle", "faces": "triangles", "curve": "cubic-bspline",
    "state": {"s": {"initial": "1/8", "next": "s/2"}},
    "definitions": {"beta_n": "(5/8 - (3/8 + cos(2*pi/n)/4)^2) / n"},
    "rules": {"edge": [{"sum": "ends", "w": "1/2 - s"}, {"sum": "opposite", "w": "s"}], "vertex": )") +
                                                         vertex_rule + "}}");
  // The same rules with s fixed at its level-1 value 1/16.
  const auto fixed = write_temp_scheme("loop-edge-16th", std::string(R"({
    "name": "loop-edge-16th", "split": "triangle", "faces": "triangles", "curve": "cubic-bspline",
    "definitions": {"beta_n": "(5/8 - (3/8 + cos(2*pi/n)/4)^2) / n"},
    "rules": {"edge": [{"sum": "ends", "w": "7/16"}, {"sum": "opposite", "w": "1/16"}], "vertex": )") +
                                                         vertex_rule + "}}");
  const Mesh mesh = octahedron();
  const auto mine = refine_mesh(mesh, file.string(), 2);
  // Level 0 is Loop's step; level 1 is the step with s = 1/16.
  const auto loop = refine_mesh(mesh, "loop", 1);
  RefineOptions one;
  one.levels = 1;
  const Hierarchy second = refine(*load_scheme(fixed.string()), loop.hierarchy.levels[1], one);
  const auto expected = interpolate(second, 1, loop.positions, 3);
  REQUIRE(mine.positions.size() == expected.size());
  for (size_t i = 0; i < expected.size(); ++i) CHECK(mine.positions[i] == doctest::Approx(expected[i]).epsilon(1e-14));
  // And it is not plain Loop at level 2.
  const auto loop2 = refine_mesh(mesh, "loop", 2);
  double difference = 0;
  for (size_t i = 0; i < expected.size(); ++i) difference = std::max(difference, std::abs(loop2.positions[i] - mine.positions[i]));
  CHECK(difference > 1e-3);
  // A state name that clashes with a parameter is refused.
  const auto clash = write_temp_scheme("state-clash", R"({
    "name": "clash", "kind": "curve", "parameters": {"a": {"default": 1}},
    "state": {"a": {"initial": "1", "next": "a"}},
    "rules": [{"start": 0, "w": ["1"]}, {"start": 0, "w": ["1/2", "1/2"]}]
  })");
  CHECK_THROWS_WITH_AS(load_curve(clash.string()), doctest::Contains("state.a: the state variable name 'a' is already"),
                       Error);
}
