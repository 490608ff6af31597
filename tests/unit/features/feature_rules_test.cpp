// Crease, dart and corner rules against their closed forms (DeRose, Kass, Truong 1998, with
// OpenSubdiv's conventions): stencil weights for Catmull-Clark on a regular grid, sharpness
// decrement per level, fractional blends, Chaikin sharpness, and OBJ tags reaching the engine.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/refine/child_tags.h"
#include "framework/features/feature_context.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"
#include "unit/features/feature_meshes.h"

using namespace subdiv;
using namespace subdiv::feature_test;
using subdiv::test::weight_of;

namespace {

constexpr int kN = 6;  // 6 x 6 quads; vertex (3, 3) is regular and far from the boundary
Index at(int i, int j) { return grid_id(i, j, kN); }

Hierarchy refine_features(const FeatureMesh& m, int levels, CreaseMethod method = CreaseMethod::Uniform,
                          const std::string& scheme = "catmull-clark") {
  RefineOptions o;
  o.levels = levels;
  o.features.crease_method = method;
  return refine(*load_scheme(scheme), level_from_mesh(m.mesh, m.name), o);
}

// Catmull-Clark weights around a regular (valence 4) interior vertex v whose crease runs
// through ring neighbours a and b, as one row: `crease` of the crease rule (3/4, 1/8, 1/8)
// plus 1 - crease of the smooth rule (9/16 on v, 3/32 on each edge neighbour, 1/64 on each
// diagonal neighbour).
struct RegularRow {
  double self, along, across, diagonal;
};
RegularRow blended_vertex_row(double crease) {
  return {crease * 3.0 / 4 + (1 - crease) * 9.0 / 16, crease / 8 + (1 - crease) * 3.0 / 32, (1 - crease) * 3.0 / 32,
          (1 - crease) / 64};
}

// Checks the stencil row of regular grid vertex v at level l against `w`, with `a`, `b`
// its neighbours along the crease.
void check_vertex_row(const Hierarchy& h, int l, Index v, Index a, Index b, const RegularRow& w) {
  const Level& L = h.levels[size_t(l)];
  const StencilTable& t = h.stencils[size_t(l)];
  REQUIRE(L.valence(v) == 4);
  CHECK(weight_of(t, v, v) == doctest::Approx(w.self).epsilon(1e-15));
  for (Index e : L.ring_edges(v)) {
    const Index u = L.other_end(e, v);
    CHECK(weight_of(t, v, u) == doctest::Approx(u == a || u == b ? w.along : w.across).epsilon(1e-15));
  }
  for (Index f : L.ring_faces(v))
    for (Index u : L.face(f))
      if (find_edge(L, u, v) == kNone && u != v) CHECK(weight_of(t, v, u) == doctest::Approx(w.diagonal).epsilon(1e-15));
  CHECK(t.row_size(v) == (w.diagonal == 0 ? 3 : 9));
}

// The new point of edge e: `crease` of the midpoint rule plus 1 - crease of the smooth rule
// (3/8 on each end, 1/16 on the four other corners of the two quads).
void check_edge_row(const Hierarchy& h, int l, Index e, double crease) {
  const Level& L = h.levels[size_t(l)];
  const StencilTable& t = h.stencils[size_t(l)];
  const Index row = L.vertex_count + e;
  const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
  CHECK(weight_of(t, row, a) == doctest::Approx(crease / 2 + (1 - crease) * 3.0 / 8).epsilon(1e-15));
  CHECK(weight_of(t, row, b) == doctest::Approx(crease / 2 + (1 - crease) * 3.0 / 8).epsilon(1e-15));
  for (int side = 0; side < 2; ++side)
    for (Index u : L.face(L.edge_faces[2 * e + side]))
      if (u != a && u != b) CHECK(weight_of(t, row, u) == doctest::Approx((1 - crease) / 16).epsilon(1e-15));
  CHECK(t.row_size(row) == (crease == 1 ? 2 : 6));
}

FeatureMesh grid_with_crease(double s) {
  FeatureMesh m = grid(kN, kN);
  std::vector<Index> row;
  for (int i = 0; i <= kN; ++i) row.push_back(at(i, 3));
  m.crease_path(row, s);
  return m;
}

// The crease neighbours of vertex v = (3, 3) level by level: at level 0 the grid vertices
// (2, 3) and (4, 3); below, the new points of the crease edges next to v.
struct CreaseWalk {
  Index left, right;
  Index left_edge, right_edge;
};
std::vector<CreaseWalk> walk(const Hierarchy& h, Index v) {
  std::vector<CreaseWalk> out;
  Index a = at(2, 3), b = at(4, 3);
  for (size_t l = 0; l < h.levels.size(); ++l) {
    const Level& L = h.levels[l];
    const Index ea = find_edge(L, v, a), eb = find_edge(L, v, b);
    out.push_back({a, b, ea, eb});
    a = L.vertex_count + ea, b = L.vertex_count + eb;
  }
  return out;
}

}  // namespace

TEST_CASE("a crease of sharpness 2 is sharp for two levels and smooth after") {
  const Hierarchy h = refine_features(grid_with_crease(2), 4);
  const Index v = at(3, 3);
  const auto w = walk(h, v);
  const float expected_sharpness[] = {2, 1, 0, 0, 0};
  const Context expected_rule[] = {Context::Crease, Context::Crease, Context::Smooth, Context::Smooth};
  for (int l = 0; l <= 4; ++l) {
    CAPTURE(l);
    CHECK(h.levels[l].edge_sharp(w[l].right_edge) == expected_sharpness[l]);
    CHECK(h.levels[l].edge_sharp(w[l].left_edge) == expected_sharpness[l]);
  }
  for (int l = 0; l < 4; ++l) {
    CAPTURE(l);
    const FeatureContexts fc = classify_features(h.levels[l], {});
    const bool sharp = l < 2;
    CHECK(fc.vertices[v].parent == expected_rule[l]);
    // Level 1 has sharpness 1: it decays to 0 below, but the fractional weight is the mean
    // decaying sharpness, 1, so the rule is still the full crease rule.
    check_vertex_row(h, l, v, w[l].left, w[l].right, blended_vertex_row(sharp ? 1 : 0));
    check_edge_row(h, l, w[l].right_edge, sharp ? 1 : 0);
  }
}

TEST_CASE("fractional sharpness blends the crease and smooth rules linearly") {
  const Index v = at(3, 3);
  SUBCASE("sharpness 0.5: half crease, half smooth at level 0, smooth after") {
    const Hierarchy h = refine_features(grid_with_crease(0.5), 2);
    const auto w = walk(h, v);
    check_vertex_row(h, 0, v, w[0].left, w[0].right, blended_vertex_row(0.5));
    check_edge_row(h, 0, w[0].right_edge, 0.5);
    check_vertex_row(h, 1, v, w[1].left, w[1].right, blended_vertex_row(0));
  }
  SUBCASE("sharpness 1.25: sharp at level 0, a quarter crease at level 1") {
    const Hierarchy h = refine_features(grid_with_crease(1.25), 3);
    const auto w = walk(h, v);
    check_vertex_row(h, 0, v, w[0].left, w[0].right, blended_vertex_row(1));
    check_edge_row(h, 0, w[0].right_edge, 1);
    check_vertex_row(h, 1, v, w[1].left, w[1].right, blended_vertex_row(0.25));
    check_edge_row(h, 1, w[1].right_edge, 0.25);
    check_vertex_row(h, 2, v, w[2].left, w[2].right, blended_vertex_row(0));
  }
  SUBCASE("different fractional sharpness on the two crease edges: the vertex blends by their mean") {
    FeatureMesh m = grid(kN, kN);
    m.crease(at(2, 3), at(3, 3), 0.25);
    m.crease(at(3, 3), at(4, 3), 0.75);
    const Hierarchy h = refine_features(m, 1);
    check_vertex_row(h, 0, v, at(2, 3), at(4, 3), blended_vertex_row(0.5));
    check_edge_row(h, 0, find_edge(h.levels[0], v, at(2, 3)), 0.25);
    check_edge_row(h, 0, find_edge(h.levels[0], v, at(4, 3)), 0.75);
  }
}

TEST_CASE("darts take the smooth rule; three crease edges or a corner tag keep a vertex fixed") {
  FeatureMesh m = grid(kN, kN);
  m.crease_path({at(1, 3), at(2, 3), at(3, 3)}, 10);         // ends at (3, 3): a dart
  m.crease_path({at(4, 2), at(4, 3), at(4, 4)}, 10);         // (4, 3) a crease vertex...
  m.crease(at(4, 3), at(5, 3), 10);                          // ... made a corner by a third edge
  m.corner(at(2, 1), 10);                                    // a tagged corner
  m.corner(at(4, 5), 0.5);                                   // a semi-sharp tagged corner
  const Hierarchy h = refine_features(m, 1);
  const FeatureContexts fc = classify_features(h.levels[0], {});
  CHECK(fc.vertices[at(3, 3)].parent == Context::Dart);
  CHECK(fc.vertices[at(1, 3)].parent == Context::Dart);
  CHECK(fc.vertices[at(2, 3)].parent == Context::Crease);
  CHECK(fc.vertices[at(4, 3)].parent == Context::Corner);
  CHECK(fc.vertices[at(2, 1)].parent == Context::Corner);
  check_vertex_row(h, 0, at(3, 3), kNone, kNone, blended_vertex_row(0));
  check_vertex_row(h, 0, at(1, 3), kNone, kNone, blended_vertex_row(0));
  for (Index corner : {at(4, 3), at(2, 1)}) {
    CHECK(h.stencils[0].row_size(corner) == 1);
    CHECK(weight_of(h.stencils[0], corner, corner) == 1.0);
  }
  // Corner sharpness 0.5: half the corner rule (the vertex itself) and half the smooth rule.
  const RegularRow smooth = blended_vertex_row(0);
  check_vertex_row(h, 0, at(4, 5), kNone, kNone, {0.5 + 0.5 * smooth.self, 0.5 * smooth.along, 0.5 * smooth.across,
                                                  0.5 * smooth.diagonal});
  // The dart's edge is a crease edge all the same: its new point is the midpoint.
  check_edge_row(h, 0, find_edge(h.levels[0], at(2, 3), at(3, 3)), 1);
}

TEST_CASE("sharpness decrement and the Chaikin rule match Sdc::Crease's formulas") {
  SUBCASE("uniform: s - 1, floored at 0; infinitely sharp stays") {
    CHECK(decremented_sharpness(2.7f) == 2.7f - 1.f);
    CHECK(decremented_sharpness(1.f) == 0.f);
    CHECK(decremented_sharpness(0.5f) == 0.f);
    CHECK(decremented_sharpness(10.f) == 10.f);
    CHECK(decremented_sharpness(25.f) == 10.f);
  }
  SUBCASE("Chaikin: 3/4 own sharpness + 1/4 mean of the other semi-sharp edges at the vertex, minus 1") {
    FeatureMesh m = grid(kN, kN);
    m.crease(at(2, 3), at(3, 3), 3);
    m.crease(at(3, 3), at(4, 3), 1);
    m.crease(at(4, 3), at(5, 3), 10);  // infinitely sharp edges do not count in the mean
    m.crease(at(3, 3), at(3, 4), 2);
    const Level L = level_from_mesh(m.mesh, "grid");
    const Index e3 = find_edge(L, at(2, 3), at(3, 3)), e1 = find_edge(L, at(3, 3), at(4, 3)),
                e2 = find_edge(L, at(3, 3), at(3, 4));
    const auto chaikin = CreaseMethod::Chaikin;
    // At (3, 3): semi-sharp edges 3, 1, 2.
    CHECK(child_edge_sharpness(L, e3, at(3, 3), chaikin) == doctest::Approx(0.75 * 3 + 0.25 * 1.5 - 1));
    CHECK(child_edge_sharpness(L, e1, at(3, 3), chaikin) == doctest::Approx(0.75 * 1 + 0.25 * 2.5 - 1));
    CHECK(child_edge_sharpness(L, e2, at(3, 3), chaikin) == doctest::Approx(0.75 * 2 + 0.25 * 2 - 1));
    // At (2, 3) the 3 is alone: decremented. At (4, 3) the 1 meets only a sharp 10: 0.
    CHECK(child_edge_sharpness(L, e3, at(2, 3), chaikin) == 2.f);
    CHECK(child_edge_sharpness(L, e1, at(4, 3), chaikin) == 0.f);
    CHECK(child_edge_sharpness(L, e1, at(3, 3), CreaseMethod::Uniform) == 0.f);
    // The around-vertex form gives the same values.
    const auto ring = L.ring_edges(at(3, 3));
    std::vector<float> parent, child(ring.size());
    for (Index e : ring) parent.push_back(L.edge_sharp(e));
    subdivide_sharpness_around_vertex(parent, child, chaikin);
    for (size_t i = 0; i < ring.size(); ++i) CHECK(child[i] == child_edge_sharpness(L, ring[i], at(3, 3), chaikin));
    // Propagated to the child level: the half of edge e3 next to (3, 3).
    RefineOptions o;
    o.levels = 1;
    o.features.crease_method = chaikin;
    const Hierarchy h = refine_topology(*load_scheme("catmull-clark"), L, o);
    CHECK(h.levels[1].edge_sharp(find_edge(h.levels[1], at(3, 3), L.vertex_count + e3)) ==
          child_edge_sharpness(L, e3, at(3, 3), chaikin));
  }
}

TEST_CASE("OBJ 't crease' and 't corner' tags reach the engine") {
  const auto dir = std::filesystem::temp_directory_path() / "subdivkit-features-obj";
  std::filesystem::create_directories(dir);
  const auto file = dir / "grid.obj";
  {
    // A 3 x 3 grid (vertices numbered from 0 in tags), a crease across the middle row of
    // vertices 4..7 and a corner tag on vertex 9.
    std::ofstream out(file);
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) out << "v " << i << ' ' << j << ' ' << 0.1 * ((i * 7 + j * 3) % 5) << '\n';
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const int v = 4 * j + i + 1;
        out << "f " << v << ' ' << v + 1 << ' ' << v + 5 << ' ' << v + 4 << '\n';
      }
    out << "t crease 2/1/0 4 5 10\nt crease 2/1/0 5 6 10\nt crease 2/1/0 6 7 2.5\nt corner 1/1/0 9 10\n";
  }
  const MeshData mesh = read_mesh(file);
  const Level L = level_from_mesh(mesh, file.string());
  CHECK(L.edge_sharp(find_edge(L, 4, 5)) == 10.f);
  CHECK(L.edge_sharp(find_edge(L, 5, 6)) == 10.f);
  CHECK(L.edge_sharp(find_edge(L, 6, 7)) == 2.5f);
  CHECK(L.edge_sharp(find_edge(L, 5, 9)) == 0.f);
  CHECK(L.vertex_sharp(9) == 10.f);
  RefineOptions o;
  o.levels = 1;
  const Hierarchy h = refine(*load_scheme("catmull-clark"), L, o);
  const StencilTable& t = h.stencils[0];
  // Vertex 5 lies on the crease: cubic B-spline along it. Vertex 9 is a tagged corner.
  CHECK(t.row_size(5) == 3);
  CHECK(weight_of(t, 5, 5) == 0.75);
  CHECK(weight_of(t, 5, 4) == 0.125);
  CHECK(weight_of(t, 5, 6) == 0.125);
  CHECK(t.row_size(9) == 1);
  CHECK(weight_of(t, 9, 9) == 1.0);
  // Crease edges: midpoints.
  const Index e = find_edge(L, 5, 6);
  CHECK(weight_of(t, L.vertex_count + e, 5) == 0.5);
  CHECK(weight_of(t, L.vertex_count + e, 6) == 0.5);
}
