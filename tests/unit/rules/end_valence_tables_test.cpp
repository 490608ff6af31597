// Weight tables of the end valences n0, n1 (framework/rules/weight_tables.h): with the
// level's valences known they are tabulated at those only, so their size no longer grows
// with the cube of the largest valence, and every weight is the formula's value.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "framework/scheme/scheme_registry.h"
#include "framework/scheme/step_tables.h"

using namespace subdiv;

namespace {

const CompiledTerm& edge_term(const WeightTables& t, Role role) {
  for (const CompiledTerm& term : t.rule(Element::Edge, Context::Smooth).terms)
    if (term.role == role) return term;
  FAIL("no such term");
  return t.rule(Element::Edge, Context::Smooth).terms.front();
}

}  // namespace

TEST_CASE("modified butterfly's end-ring weights at a 300-valent hub are tabulated at the valences present") {
  const auto scheme = load_scheme("modified-butterfly");
  const std::vector<int> valences = {4, 300};
  const WeightTables t = step_weight_tables(*scheme, scheme->steps.front(), 300, 3, 0, nullptr, &valences);
  const CompiledTerm& ring0 = edge_term(t, Role::EndRing0);
  // Dense: 301 x 301 x 301 entries; here 2 x 2 x 301 at most, times the two ends' feature
  // flags b0, b1 (an end on a boundary or crease takes its sector stencil instead).
  CHECK(ring0.table.size() <= 2 * 2 * 301 * 2 * 2);
  // Zorin, Schröder & Sweldens 1996: s_j = (1/4 + cos(2 pi j/n) + cos(4 pi j/n)/2)/n for
  // n >= 5; both ends extraordinary (300 and 4), so each end's stencil counts 1/2.
  const double pi = std::numbers::pi;
  for (int j : {0, 1, 7, 150, 299}) {
    const double s = (0.25 + std::cos(2 * pi * j / 300) + 0.5 * std::cos(4 * pi * j / 300)) / 300;
    CHECK(ring0.weight(2, 0, j, 300, 4) == doctest::Approx(0.5 * s).epsilon(1e-14));
  }
  // Valence 4 at end 0 next to the hub: s = (3/8, 0, -1/8, 0), halved.
  CHECK(ring0.weight(2, 0, 0, 4, 300) == doctest::Approx(3.0 / 16));
  CHECK(ring0.weight(2, 0, 2, 4, 300) == doctest::Approx(-1.0 / 16));
  CHECK(ring0.weight(2, 0, 1, 4, 300) == doctest::Approx(0.0));
}
