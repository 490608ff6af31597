// Limit points and normals where no limit mask exists (issue 33): a non-manifold edge or a
// duplicated face stays so at every level, so refining to find an analysable
// neighbourhood can never succeed (it ran 12 levels of refinement, 5-73 s on 5-8 vertices).
// Such vertices get a defined answer at once: their own position, marked not exact, with
// the reason.
#include <doctest/doctest.h>

#include <chrono>
#include <string>
#include <vector>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/topology/level.h"

using namespace subdiv;

namespace {

struct Case {
  const char* name;
  const char* scheme;
  Index vertices;
  std::vector<Index> offsets, corners;
};

}  // namespace

TEST_CASE("limits: non-manifold and duplicated neighbourhoods are answered at once, not searched for 12 levels") {
  const std::vector<Case> cases = {
      // Three triangles on the edge 0-1.
      {"non-manifold edge", "loop", 5, {0, 3, 6, 9}, {0, 1, 2, 1, 0, 3, 0, 1, 4}},
      // A quad and its duplicate with a neighbour.
      {"duplicated face", "catmull-clark", 6, {0, 4, 8, 12}, {0, 1, 2, 3, 0, 1, 2, 3, 1, 4, 5, 2}},
  };
  for (const Case& c : cases) {
    CAPTURE(std::string(c.name));
    const Level level = build_level(c.vertices, c.offsets, c.corners);
    REQUIRE(!level.manifold());
    std::vector<double> positions;
    for (Index v = 0; v < c.vertices; ++v) positions.insert(positions.end(), {double(v), double(v * v % 7), 0.5 * v});
    const auto start = std::chrono::steady_clock::now();
    const LimitResult r = limit_positions(*load_scheme(c.scheme), level, positions);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(2));
    for (Index v = 0; v < c.vertices; ++v) {
      if (!level.non_manifold_vertex(v)) continue;
      CHECK(!r.exact[size_t(v)]);
      for (int k = 0; k < 3; ++k) CHECK(r.positions[size_t(3 * v + k)] == positions[size_t(3 * v + k)]);
    }
    REQUIRE(!r.approximate_reasons.empty());
    bool named = false;
    for (const std::string& reason : r.approximate_reasons) named = named || reason.find("non-manifold") != std::string::npos;
    CHECK(named);
  }
}
