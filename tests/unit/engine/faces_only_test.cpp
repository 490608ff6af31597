// RefineOptions::faces_only_last_level (framework/engine/refiner.h): the last level built as
// OpenSubdiv's default UniformOptions builds it, faces only.
#include <doctest/doctest.h>

#include "framework/engine/evaluator.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

// RefineOptions::faces_only_last_level: the last level's faces, vertex count and origins as
// with full topology, and the same values from step_values; levels with smoothing
// passes keep full topology.
TEST_CASE("a faces-only last level has the full level's faces and gives the same values") {
  for (const auto& case_ : {std::pair{"catmull-clark", torus(6, 5)}, std::pair{"catmull-clark", pyramid()},
                                   std::pair{"loop", grid(4, 3, true)}, std::pair{"sqrt3", torus(6, 5, true)},
                                   std::pair{"sqrt3", grid(4, 3, true)}, std::pair{"doo-sabin", torus(6, 5)},
                                   std::pair{"doo-sabin", pyramid()}, std::pair{"mid-edge", grid(4, 3)},
                                   std::pair{"loop-composite", torus(6, 5, true)}}) {
    const auto& [name, mesh] = case_;
    const std::string scheme_name = name;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
    CAPTURE(scheme_name);
    const auto scheme = load_scheme(name);
    RefineOptions full, faces;
    full.levels = faces.levels = 2;
    faces.faces_only_last_level = true;
    const Hierarchy a = refine_topology(*scheme, mesh.level(), full);
    const Hierarchy b = refine_topology(*scheme, mesh.level(), faces);
    const Level &la = a.levels.back(), &lb = b.levels.back();
    CHECK(la.vertex_count == lb.vertex_count);
    CHECK(la.face_offsets == lb.face_offsets);
    CHECK(la.face_vertices == lb.face_vertices);
    CHECK(a.origins.back().kind == b.origins.back().kind);
    CHECK(a.origins.back().parent == b.origins.back().parent);
    // Splits with a faces-only variant (all built-in ones) and one step per level stop short.
    const bool one_step = std::string(name) != "loop-composite";
    CHECK(lb.edge_count() == (one_step ? 0 : la.edge_count()));
    std::vector<double> va = mesh.positions, vb = mesh.positions;
    for (int l = 0; l < 2; ++l) va = step_values(*scheme, a, l, va, 3, full), vb = step_values(*scheme, b, l, vb, 3, faces);
    CHECK(va == vb);
    CHECK(a.levels[1].edge_count() == b.levels[1].edge_count());  // only the last level is cut short
  }
}

// A last level larger than the caches (32 MB of corners and of points) is written with
// streaming stores (util/streaming_stores.h): its faces-only corners must be the full
// split's, and step_values' points (the vertex points streamed) the Evaluator's, which
// streams nothing and gives step_values' bits (engine/evaluator.h).
TEST_CASE("a large last level written with streaming stores has the same faces and bits") {
  for (const auto& case_ : {std::pair{"catmull-clark", torus(800, 700)}, std::pair{"loop", torus(1000, 600, true)}}) {
    const auto& [name, mesh] = case_;
    const std::string scheme_name = name;
    CAPTURE(scheme_name);
    const auto scheme = load_scheme(name);
    RefineOptions full, faces;
    faces.faces_only_last_level = true;
    const Hierarchy a = refine_topology(*scheme, mesh.level(), full);
    const Hierarchy b = refine_topology(*scheme, mesh.level(), faces);
    REQUIRE(b.levels.back().face_vertices.size() * sizeof(Index) >= (size_t(32) << 20));
    CHECK(a.levels.back().face_offsets == b.levels.back().face_offsets);
    CHECK(a.levels.back().face_vertices == b.levels.back().face_vertices);
    const std::vector<double> streamed = step_values(*scheme, b, 0, mesh.positions, 3, faces);
    REQUIRE(streamed.size() * sizeof(double) >= (size_t(32) << 20));
    CHECK(streamed == Evaluator(*scheme, a, full).evaluate(mesh.positions, 3));
  }
}
