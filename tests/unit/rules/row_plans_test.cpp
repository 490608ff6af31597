// Row plans (framework/rules/row_plans.h) replay learnt rows for smooth interior elements.
// They must give exactly the generic interpreter's rows, entry for entry, for every scheme
// and mesh, and must really be used where they apply.
#include <doctest/doctest.h>

#include "framework/refine/splitter.h"
#include "framework/rules/row_plans.h"
#include "framework/rules/step_rows.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/step_tables.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

Hierarchy refine_with(const std::string& scheme, const Level& level, bool plans, int levels = 2) {
  RefineOptions o;
  o.levels = levels;
  o.evaluation.use_row_plans = plans;
  return refine(*load_scheme(scheme), level, o);
}

void check_same_tables(const std::string& scheme, const Level& level, int levels = 2) {
  const Hierarchy with = refine_with(scheme, level, true, levels), without = refine_with(scheme, level, false, levels);
  REQUIRE(with.stencils.size() == without.stencils.size());
  for (size_t l = 0; l < with.stencils.size(); ++l) {
    CAPTURE(scheme);
    CAPTURE(l);
    CHECK(with.stencils[l].offsets == without.stencils[l].offsets);
    CHECK(with.stencils[l].indices == without.stencils[l].indices);
    CHECK(with.stencils[l].weights == without.stencils[l].weights);  // bit for bit
  }
}

// A cube with one sharp edge, one semi-sharp edge (1.5) and a sharp corner: features next
// to smooth vertices, so plans and the generic path meet.
Level creased_cube() {
  Level L = cube().level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  L.edge_sharpness[0] = 10.f;
  L.edge_sharpness[5] = 1.5f;
  L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
  L.vertex_sharpness[6] = 3.f;
  return L;
}

}  // namespace

TEST_CASE("row plans give the generic rows, bit for bit, for every kind of scheme") {
  const std::vector<Level> quads = {torus(6, 5).level(), cube().level(), grid(4, 3).level(), creased_cube(),
                                    torus(3, 3).level()};
  const std::vector<Level> triangles = {torus(6, 5, true).level(), octahedron().level(), grid(4, 3, true).level(),
                                        bipyramid(7).level(), torus(3, 3, true).level()};
  for (const char* scheme : {"catmull-clark", "catmull-clark-shape", "bilinear", "quad-bspline", "doo-sabin", "mid-edge"})
    for (const Level& L : quads) check_same_tables(scheme, L);
  for (const char* scheme : {"catmull-clark", "bilinear", "doo-sabin", "mid-edge"})
    check_same_tables(scheme, pyramid().level());  // a quad among triangles
  for (const char* scheme : {"loop", "loop-composite", "butterfly", "modified-butterfly", "midpoint"})
    for (const Level& L : triangles) check_same_tables(scheme, L);
  for (const Level& L : triangles) check_same_tables("sqrt3", L, 3);
  check_same_tables("catmull-clark", creased_cube(), 4);  // semi-sharp decays over levels
}

namespace {

// Replays Catmull-Clark's first step on `L` through a planner, learning from the generic
// rows; checks every replayed row against the generic one and returns how many were learnt.
int learn_and_replay(const Level& L) {
  const auto scheme = load_scheme("catmull-clark");
  const SplitResult split = split_quad(L);
  const WeightTables tables = step_weight_tables(*scheme, scheme->steps.front(), 8, 4, 0);
  const FeatureContexts features = classify_features(L, {});
  RowPlanStore store(L, split.origins, tables, features, false);
  REQUIRE(store.enabled[int(Element::Vertex)]);
  REQUIRE(store.enabled[int(Element::Edge)]);
  REQUIRE(store.enabled[int(Element::Face)]);
  const StencilTable generic = refine_with("catmull-clark", L, false, 1).stencils[0];
  RowPlanner planner(store);
  int learnt = 0, replayed = 0;
  for (Index child = 0; child < generic.row_count(); ++child) {
    RowBlock out;
    const auto outcome = planner.try_append(child, out);
    if (outcome == RowPlanner::Outcome::Learn) {
      RowBuilder row;
      for (Index i = generic.offsets[child]; i < generic.offsets[child + 1]; ++i)
        row.add(generic.indices[i], generic.weights[i]);
      planner.learn(row, store);
      ++learnt;
      continue;
    }
    REQUIRE(outcome == RowPlanner::Outcome::Appended);
    ++replayed;
    const auto from = generic.offsets[child], to = generic.offsets[child + 1];
    CHECK(std::vector<Index>(out.indices.begin(), out.indices.end()) ==
          std::vector<Index>(generic.indices.begin() + from, generic.indices.begin() + to));
    CHECK(std::vector<double>(out.weights.begin(), out.weights.end()) ==
          std::vector<double>(generic.weights.begin() + from, generic.weights.begin() + to));
  }
  CHECK(learnt + replayed == generic.row_count());
  return learnt;
}

}  // namespace

TEST_CASE("row plans are learnt once per shape and replayed everywhere else") {
  // A regular torus has a handful of shapes (one vertex shape; edges and faces differ only
  // by where each face starts), however large it is.
  const int small = learn_and_replay(torus(8, 6).level()), large = learn_and_replay(torus(32, 24).level());
  CHECK(small == large);
  CHECK(small <= 12);
  // A vertex rule written in C++ (a plugin) never uses plans.
  const auto scheme = load_scheme("catmull-clark");
  const Level L = torus(8, 6).level();
  const SplitResult split = split_quad(L);
  const WeightTables tables = step_weight_tables(*scheme, scheme->steps.front(), 8, 4, 0);
  const RowPlanStore code(L, split.origins, tables, classify_features(L, {}), true);
  CHECK_FALSE(code.enabled[int(Element::Vertex)]);
}

TEST_CASE("row plans stay off where a rule reads past the element's neighbourhood") {
  // The butterfly's edge rule reads the far wings, outside the edge's two triangles.
  const auto scheme = load_scheme("butterfly");
  const Level L = torus(6, 5, true).level();
  const SplitResult split = split_triangle(L);
  const WeightTables tables = step_weight_tables(*scheme, scheme->steps.front(), 6, 3, 0);
  const RowPlanStore store(L, split.origins, tables, classify_features(L, {}), false);
  CHECK_FALSE(store.enabled[int(Element::Edge)]);
}

namespace {

// Runs every child of one step through a planner in the step evaluator's mode (new points
// as sources), learning from the interpreter; returns how many took the generic path.
int generic_rows_with_sources(const std::string& name, const Level& L) {
  const auto scheme = load_scheme(name);
  const SplitResult split = L.face_size(0) == 3 ? split_triangle(L) : split_quad(L);
  const WeightTables tables = step_weight_tables(*scheme, scheme->steps.front(), 8, 4, 0);
  const FeatureContexts features = classify_features(L, {});
  const StepContext step{L, split.origins, tables, features};
  const std::vector<ChildGroup> groups = group_children(step);
  RowPlanStore store(L, split.origins, tables, features, false, &groups);
  RuleInputs in{L, features};
  in.groups = &groups;
  in.new_point_base = L.vertex_count;
  RowPlanner planner(store);
  int generic = 0;
  for (Index child = 0; child < Index(split.origins.kind.size()); ++child) {
    RowPlanner::Outcome outcome;
    if (planner.find(child, outcome)) continue;
    if (outcome == RowPlanner::Outcome::Generic) {
      ++generic;
      continue;
    }
    RowBuilder row;
    fill_row(row, step, in, child);
    planner.learn(row, store);
  }
  return generic;
}

}  // namespace

TEST_CASE("with new points as sources (step_values), plans cover every smooth interior element") {
  CHECK(generic_rows_with_sources("catmull-clark", torus(8, 6).level()) == 0);
  CHECK(generic_rows_with_sources("loop", torus(8, 6, true).level()) == 0);
  CHECK(generic_rows_with_sources("bilinear", torus(8, 6).level()) == 0);
  // The butterfly's edges read past the enumeration: generic, as with tables.
  CHECK(generic_rows_with_sources("butterfly", torus(8, 6, true).level()) > 0);
}
