// Weight tables of the end valences n0, n1 and of the ends' sectors (framework/rules/
// weight_tables.h): with the level's valences and sector sizes known they are tabulated at
// those only, so their size no longer grows with the cube of the largest valence, and every
// weight is the formula's value.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

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
  const LevelValences present{{4, 300}, {}};  // a closed fan: no sectors
  const WeightTables t = step_weight_tables(*scheme, scheme->steps.front(), 300, 3, 0, nullptr, &present);
  const CompiledTerm& ring0 = edge_term(t, Role::EndRing0);
  // Dense: 301 x 301 x 301 entries; here 2 x 2 x 301 at most, times the two ends' feature
  // flags b0, b1 (an end on a boundary or crease takes its sector stencil instead).
  CHECK(ring0.table.size() <= 2 * 2 * 301 * 2 * 2);
  CHECK(edge_term(t, Role::EndSector0).table.size() <= 301 * 2 * 2);
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

TEST_CASE("modified butterfly's sector weights at a 300-valent boundary hub are tabulated at the sector sizes present") {
  // A fan of 300 triangles from a boundary vertex: sectors of 300 faces (the hub), 2 (the
  // rim) and 1 (the rim's ends).
  const auto scheme = load_scheme("modified-butterfly");
  const LevelValences present{{2, 3, 301}, {1, 2, 300}};
  const WeightTables t = step_weight_tables(*scheme, scheme->steps.front(), 301, 3, 0, nullptr, &present);
  const CompiledTerm& sector0 = edge_term(t, Role::EndSector0);
  // Over j <= 301, b0, b1 and the (m0, e0) pairs 0 <= e0 <= m0 of m0 in {0, 1, 2, 300}: 307
  // pairs, where every m0, e0 <= 301 would be 302 x 302.
  CHECK(sector0.table.size() <= 302 * 2 * 2 * 307);
  // SubdivKit's sector stencil (docs/features.md): s_j = c_j cos((j - e) pi / m) / m, c_j = 1/2
  // at j = 0, m; an end alone takes it whole, two ends half each.
  const double pi = std::numbers::pi;
  auto weight = [&](int j, int m, int e, bool both) {
    SectorVariables s;
    s.b[0] = 1, s.m[0] = m, s.e[0] = e;
    if (both) s.b[1] = 1, s.m[1] = 2, s.e[1] = 1;
    return sector0.edge_weight(3, j, 301, 3, 3, 3, s);
  };
  for (int e : {1, 150, 299})
    for (int j : {0, 1, e, 151, 300}) {
      CAPTURE(e);
      CAPTURE(j);
      const double s = (j == 0 || j == 300 ? 0.5 : 1.0) * std::cos((j - e) * pi / 300) / 300;
      CHECK(weight(j, 300, e, false) == doctest::Approx(s).epsilon(1e-14));
      CHECK(weight(j, 300, e, true) == doctest::Approx(0.5 * s).epsilon(1e-14));
    }
  // The rim's sector of two faces: (0, 1/2, 0) around the edge to p_1.
  CHECK(weight(1, 2, 1, false) == doctest::Approx(0.5));
  CHECK(weight(0, 2, 1, false) == doctest::Approx(0.0));
}

TEST_CASE("only rules over the ends' sectors ask for the level's sector sizes") {
  // prepare_step finds the sector sizes (a pass over every ring of a tagged level) only for
  // tables that read them: modified butterfly's edge rule does, Loop's and Catmull-Clark's do not.
  for (const char* name : {"loop", "catmull-clark", "modified-butterfly"}) {
    CAPTURE(name);
    const auto scheme = load_scheme(name);
    const LevelValences present{{3, 6}, {}};
    const WeightTables t = step_weight_tables(*scheme, scheme->steps.front(), 6, 4, 0, nullptr, &present);
    CHECK(reads_sector_sizes(t) == (std::string(name) == "modified-butterfly"));
  }
}
