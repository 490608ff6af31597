// Every built-in split on non-manifold input: the primal ones refine it (their agreement with
// OpenSubdiv is in osd_*_test.cpp) and keep the marks; the dual ones give a valid mesh with
// one warning saying where they left a gap; sqrt3 is in sqrt3_nonmanifold_test.cpp.
#include <doctest/doctest.h>

#include <cmath>

#include "framework/engine/refiner.h"
#include "framework/io/mesh_level.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "unit/topology/nonmanifold_meshes.h"

using namespace subdiv;
using namespace subdiv::nonmanifold_test;

namespace {

Hierarchy refined(const feature_test::FeatureMesh& m, const std::string& scheme, int levels) {
  RefineOptions options;
  options.levels = levels;
  return refine(*load_scheme(scheme), level_from_mesh(m.mesh, m.name), options);
}

bool all_finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace

TEST_CASE("primal splits keep a non-manifold edge non-manifold, with its faces' children on its halves") {
  const auto m = flap_fan(3, false);
  const Hierarchy h = refined(m, "catmull-clark", 2);
  for (int l = 1; l <= 2; ++l) {
    const Level& L = h.levels[size_t(l)];
    CHECK_FALSE(L.manifold());
    // The hinge from vertex 0 to vertex 1 is cut in 2^l pieces, each with 3 faces.
    int hinge_pieces = 0;
    for (Index e = 0; e < L.edge_count(); ++e)
      if (L.non_manifold_edge(e)) {
        CHECK(L.edge_face_count(e) == 3);
        ++hinge_pieces;
      }
    CHECK(hinge_pieces == (1 << l));
  }
  CHECK(h.warnings.empty());
}

// Doo-Sabin's feature split takes non-manifold elements as features, as OpenSubdiv tags them
// (a non-manifold edge infinitely sharp, a non-manifold vertex a corner): the flaps stay
// joined along their hinge and the bow-tie's grids at their shared vertex, at every level,
// with no gap to warn about.
TEST_CASE("Doo-Sabin keeps non-manifold hinges and pinches joined") {
  for (const auto& m : {flap_fan(3, false), bow_tie(false)}) {
    CAPTURE(m.name);
    const Hierarchy h = refined(m, "doo-sabin", 2);
    CHECK(h.warnings.empty());
    for (int l = 1; l <= 2; ++l) {
      const Level& L = h.levels[size_t(l)];
      int joined = 0;
      for (Index v = 0; v < L.vertex_count; ++v) joined += L.non_manifold_vertex(v) ? 1 : 0;
      CHECK(joined >= 1);
    }
    CHECK(all_finite(interpolate(h, 2, m.mesh.positions, 3)));
  }
}

// Mid-edge has no face at a non-manifold vertex (no cycle of faces to take the midpoints of).
TEST_CASE("mid-edge on non-manifold input: a valid mesh and one warning") {
  for (const auto& m : {flap_fan(3, false), bow_tie(false)}) {
    CAPTURE(m.name);
    const Hierarchy h = refined(m, "mid-edge", 2);
    // One warning per level that met non-manifold elements (at most one per level).
    REQUIRE(!h.warnings.empty());
    CHECK(h.warnings.size() <= 2);
    CHECK(h.warnings[0].find("level 1: ") == 0);
    for (const auto& w : h.warnings) CHECK(w.find("non-manifold") != std::string::npos);
    CHECK(all_finite(interpolate(h, 2, m.mesh.positions, 3)));
    CHECK(h.levels[2].face_count() > 0);
  }
}

// Every shipped surface scheme on every kind of non-manifold input it accepts the faces of:
// refined with finite positions, never
// refused for being non-manifold and never a crash.
TEST_CASE("every shipped surface scheme on non-manifold input: a valid result") {
  for (const SchemeListing& listing : list_schemes()) {
    if (listing.kind != "surface" || listing.origin != "built-in") continue;
    const auto scheme = load_scheme(listing.name);
    const bool triangles = scheme->required_face_size == 3 || splitter_info(scheme->split()).required_face_size == 3;
    for (const auto& m : {flap_fan(3, triangles), flap_fan(4, triangles), bow_tie(triangles), flipped_face(triangles),
                          collapsed_faces(triangles)}) {
      CAPTURE(listing.name);
      CAPTURE(m.name);
      RefineOptions options;
      options.levels = 2;
      try {
        const Hierarchy h = refine(*scheme, level_from_mesh(m.mesh, m.name), options);
        CHECK(all_finite(interpolate(h, 2, m.mesh.positions, 3)));
      } catch (const Error& e) {
        FAIL_CHECK(std::string(e.what()));
      }
    }
  }
}
