// Progressive interpolation works for every shipped linear surface
// scheme. Each scheme file in schemes/ gets a limit operator on closed meshes it accepts
// (and on open ones, where it has vertex points), the iteration converges, and the new
// control mesh, refined deeply, approaches the targets: an independent check of the chosen
// masks, since refinement never looks at them.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "framework/interpolation/dual_limits.h"
#include "framework/interpolation/limit_selection.h"
#include "framework/interpolation/progressive.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/util/error.h"
#include "interp_reference.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// Surface schemes among the shipped files (curve schemes refine polylines, and
// scheme.schema.json is the language's schema).
std::vector<std::string> shipped_surface_schemes() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SUBDIV_SOURCE_DIR) + "/schemes")) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "scheme.schema.json") continue;
    std::ifstream in(entry.path());
    const auto json = nlohmann::json::parse(in);
    if (json.value("kind", "surface") == "curve") continue;
    names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Meshes the scheme accepts: closed ones, and one with a boundary.
std::vector<Mesh> meshes_for(const Scheme& scheme) {
  if (scheme.required_face_size == 3) return {octahedron(), bipyramid(5), grid(3, 2, true)};
  if (scheme.required_face_size == 4) return {cross_mesh(), torus(5, 4), grid(3, 2)};
  return {cross_mesh(), octahedron(), grid(3, 2)};
}

// The converged control mesh, refined `deep` levels, has vertex points at most a quarter as
// far from the targets as after 2 levels, and close: refinement converges to the limit the
// masks claim. (Dual schemes have no vertex points; their V-face test is in limits_test.)
void check_deep_refinement(const Scheme& scheme, const Level& L, const std::vector<double>& control,
                           const std::vector<double>& targets) {
  constexpr int deep = 6;
  RefineOptions o;
  o.levels = deep;
  const Hierarchy h = refine(scheme, L, o);
  std::vector<double> x = control, x2;
  for (int l = 0; l < deep; ++l) {
    x = h.stencils[l].apply(x, 3);
    if (l == 1) x2 = x;
  }
  Hierarchy two = h;
  two.levels.resize(3), two.origins.resize(2), two.stencils.resize(2);
  const auto c2 = vertex_descendants(two), c6 = vertex_descendants(h);
  for (Index v = 0; v < L.vertex_count; ++v) {
    const double e2 = dist(at(x2, c2[v]), at(targets, v)), e6 = dist(at(x, c6[v]), at(targets, v));
    CHECK(e6 <= e2 / 4 + 1e-12);
    CHECK(e6 < 0.01);
  }
}

}  // namespace

TEST_CASE("every shipped surface scheme interpolates: a limit mask, convergence, deep refinement agrees") {
  const std::vector<std::string> names = shipped_surface_schemes();
  CHECK(names.size() >= 12);
  for (const std::string& name : names) {
    const auto sequence = load_scheme_sequence(name, 1, {});
    const Scheme& scheme = *sequence.schemes.back();
    for (const Mesh& mesh : meshes_for(scheme)) {
      const Level L = mesh.level();
      const bool open = L.vertex_count > 0 && std::any_of(L.vertex_on_boundary.begin(), L.vertex_on_boundary.end(),
                                                          [](auto b) { return b != 0; });
      CAPTURE(name);
      CAPTURE(L.vertex_count);
      LimitChoice choice;
      try {
        choice = select_limit(sequence, L);
      } catch (const Error& e) {
        // The one documented gap: a dual scheme's boundary vertex has an open V-face.
        CHECK(open);
        CHECK(std::string(e.what()).find("is dual") != std::string::npos);
        continue;
      }
      const ProgressiveResult r = progressive_interpolation(*choice.evaluator, L, mesh.positions, {});
      CHECK(r.converged);
      const std::vector<double> reached = choice.evaluator->limit_stencils(L).apply(r.control, 3);
      for (Index v = 0; v < L.vertex_count; ++v) CHECK(dist(at(reached, v), at(mesh.positions, v)) < 1e-9);
      if (!dynamic_cast<const DualCentroidLimit*>(choice.evaluator.get()))
        check_deep_refinement(scheme, L, r.control, mesh.positions);
    }
  }
}
