// The sqrt3 and dual splits build their child levels from the parent's arrays
// (refine/dual_topology.h, refine/sqrt3_topology.h) and have faces-only variants for a last
// level. Both must give exactly what the generic way gives: build_level on the same child
// polygons (every array, same numbering), and the full split's faces and origins.
#include <cmath>
#include <doctest/doctest.h>
#include <functional>
#include <string>
#include <tbb/global_control.h>

#include "framework/refine/splitter.h"
#include "support/test_meshes.h"

using namespace subdiv;

namespace {

// The top half of a bipyramid: a cone with a boundary (rim vertices have two faces).
test::Mesh open_cone(int n) {
  test::Mesh m = test::bipyramid(n);
  m.offsets = {0};
  m.corners.clear();
  for (int i = 0; i < n; ++i) m.add_face({Index(i), Index((i + 1) % n), Index(n)});
  return m;
}

// A prism over a k-gon, with both caps (closed) or the top one only (a boundary at the bottom).
test::Mesh prism(int k, bool closed) {
  test::Mesh m;
  for (int ring = 0; ring < 2; ++ring)
    for (int i = 0; i < k; ++i) m.add_vertex(std::cos(2 * M_PI * i / k), std::sin(2 * M_PI * i / k), ring);
  std::vector<Index> bottom(k), top(k);
  for (int i = 0; i < k; ++i) bottom[i] = k - 1 - i, top[i] = k + i;
  if (closed) m.corners.insert(m.corners.end(), bottom.begin(), bottom.end()), m.offsets.push_back(Index(m.corners.size()));
  m.corners.insert(m.corners.end(), top.begin(), top.end()), m.offsets.push_back(Index(m.corners.size()));
  for (int i = 0; i < k; ++i) m.add_face({i, (i + 1) % k, k + (i + 1) % k, k + i});
  return m;
}

// Sharp tags on every third edge (some infinitely sharp, some boundary ones too: those are
// skipped by the splits) and on vertex 0.
Level with_creases(Level L) {
  L.edge_sharpness.assign(L.edge_count(), 0.f);
  for (Index e = 0; e < L.edge_count(); e += 3) L.edge_sharpness[e] = e % 2 ? 10.f : 2.f;
  L.vertex_sharpness.assign(L.vertex_count, 0.f);
  if (L.vertex_count) L.vertex_sharpness[0] = 3.f;
  return L;
}

struct Named {
  std::string name;
  Level level;
};

std::vector<Named> triangle_meshes() {
  std::vector<Named> out;
  for (int n = 3; n <= 12; ++n) out.push_back({"bipyramid " + std::to_string(n), test::bipyramid(n).level()});
  for (int n : {3, 5, 8}) out.push_back({"open cone " + std::to_string(n), open_cone(n).level()});
  out.push_back({"octahedron", test::octahedron().level()});
  out.push_back({"tri torus", test::torus(7, 5, true).level()});
  out.push_back({"tri grid", test::grid(4, 3, true).level()});
  out.push_back({"tri grid creased", with_creases(test::grid(5, 4, true).level())});
  out.push_back({"tri torus creased", with_creases(test::torus(6, 5, true).level())});
  out.push_back({"bipyramid creased", with_creases(test::bipyramid(7).level())});
  return out;
}

std::vector<Named> polygon_meshes() {
  std::vector<Named> out;
  for (int k = 3; k <= 8; ++k) {
    out.push_back({"closed prism " + std::to_string(k), prism(k, true).level()});
    out.push_back({"open prism " + std::to_string(k), prism(k, false).level()});
  }
  out.push_back({"cube creased", with_creases(test::cube().level())});
  out.push_back({"pyramid", test::pyramid().level()});
  out.push_back({"quad grid", test::grid(3, 2).level()});
  out.push_back({"quad grid creased", with_creases(test::grid(4, 3).level())});
  out.push_back({"quad torus", test::torus(5, 4).level()});
  for (auto& t : triangle_meshes()) out.push_back(std::move(t));
  return out;
}

// Every array of `direct` equals build_level's on its polygons.
void check_equals_generic(const Level& direct) {
  const Level g = build_level(direct.vertex_count, direct.face_offsets, direct.face_vertices);
  CHECK(direct.face_edges == g.face_edges);
  CHECK(direct.edge_vertices == g.edge_vertices);
  CHECK(direct.edge_faces == g.edge_faces);
  CHECK(direct.vertex_ring_offsets == g.vertex_ring_offsets);
  CHECK(direct.vertex_edges == g.vertex_edges);
  CHECK(direct.vertex_face_offsets == g.vertex_face_offsets);
  CHECK(direct.vertex_faces == g.vertex_faces);
  CHECK(direct.vertex_face_corner == g.vertex_face_corner);
  CHECK(direct.vertex_on_boundary == g.vertex_on_boundary);
  CHECK(direct.edge_non_manifold == g.edge_non_manifold);
  CHECK(direct.vertex_non_manifold == g.vertex_non_manifold);
  CHECK(direct.edge_face_offsets == g.edge_face_offsets);
  CHECK(direct.edge_face_list == g.edge_face_list);
}

void check_faces_only(const SplitResult& full, const SplitResult& faces) {
  CHECK(full.child.vertex_count == faces.child.vertex_count);
  CHECK(full.child.face_offsets == faces.child.face_offsets);
  CHECK(full.child.face_vertices == faces.child.face_vertices);
  CHECK(faces.child.edge_count() == 0);
  CHECK(full.origins.kind == faces.origins.kind);
  CHECK(full.origins.parent == faces.origins.parent);
  CHECK(full.origins.local == faces.origins.local);
  CHECK(full.origins.parent_face == faces.origins.parent_face);
  CHECK(full.features_refined == faces.features_refined);
  CHECK(full.warning == faces.warning);
}

using Split = std::function<SplitResult(const Level&, int step)>;
using Splits = std::pair<Split, Split>;  // full, faces only

// Two steps of a split from `base` (step indices first, first + 1), each checked.
void check_two_steps(const Level& base, int first, const Splits& s) {
  Level L = base;
  for (int step = first; step < first + 2; ++step) {
    CAPTURE(step);
    SplitResult full = s.first(L, step);
    check_equals_generic(full.child);
    check_faces_only(full, s.second(L, step));
    L = std::move(full.child);
  }
}

const Splits kSqrt3{split_sqrt3, split_sqrt3_faces};
const Splits kDual{[](const Level& L, int) { return split_dual(L); }, [](const Level& L, int) { return split_dual_faces(L); }};
const Splits kMidEdge{[](const Level& L, int) { return split_mid_edge(L); },
                      [](const Level& L, int) { return split_mid_edge_faces(L); }};

}  // namespace

TEST_CASE("sqrt3: the direct child equals build_level's, faces only equal the full split's, both parities") {
  for (const Named& m : triangle_meshes()) {
    CAPTURE(m.name);
    for (int first : {0, 1}) check_two_steps(m.level, first, kSqrt3);
  }
}

TEST_CASE("dual and mid-edge: the direct child equals build_level's, faces only equal the full split's") {
  for (const Named& m : polygon_meshes()) {
    CAPTURE(m.name);
    check_two_steps(m.level, 0, kDual);
    check_two_steps(m.level, 0, kMidEdge);
  }
}

TEST_CASE("sharp edges keep their sharpness in the direct children") {
  const Level L = with_creases(test::torus(6, 5).level());
  Index sharp = 0;
  for (Index e = 0; e < L.edge_count(); ++e) sharp += L.edge_sharpness[e] > 0.f;
  // The dual split glues the two sides of a sharp edge (docs/features.md, creases in dual
  // schemes): one sharp child edge along each sharp edge, and one across each crease vertex
  // (two sharp edges, not a corner: a corner's face corners are one point).
  Index crease_vertices = 0;
  for (Index v = 0; v < L.vertex_count; ++v) {
    int at_v = 0;
    for (Index e : L.ring_edges(v)) at_v += L.edge_sharpness[e] >= 1.f;
    crease_vertices += at_v == 2 && L.vertex_sharpness[v] < 1.f;
  }
  Index dual_sharp = 0;
  for (float s : split_dual(L).child.edge_sharpness) dual_sharp += s > 0.f;
  CHECK(dual_sharp == sharp + crease_vertices);
  const Level T = with_creases(test::torus(6, 5, true).level());
  sharp = 0;
  for (Index e = 0; e < T.edge_count(); ++e) sharp += T.edge_sharpness[e] > 0.f;
  for (int step : {0, 1}) {
    Index pieces = 0;
    for (float s : split_sqrt3(T, step).child.edge_sharpness) pieces += s > 0.f;
    CHECK(pieces == (step == 0 ? 1 : 3) * sharp);  // kept, or trisected
  }
}

TEST_CASE("the direct children are the same on one thread and on two") {
  const Level tris = test::torus(150, 120, true).level(), quads = test::torus(140, 110).level();
  const Level grid = test::grid(150, 120, true).level();
  std::vector<Level> one;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    std::vector<Level> got{split_sqrt3(tris, 0).child, split_sqrt3(grid, 0).child, split_sqrt3(grid, 1).child,
                           split_dual(quads).child,    split_dual(grid).child,     split_mid_edge(quads).child,
                           split_mid_edge(grid).child};
    if (threads == 1) {
      for (const Level& c : got) check_equals_generic(c);
      one = std::move(got);
      continue;
    }
    for (size_t i = 0; i < got.size(); ++i) {
      CAPTURE(i);
      CHECK(got[i].face_vertices == one[i].face_vertices);
      CHECK(got[i].face_edges == one[i].face_edges);
      CHECK(got[i].edge_vertices == one[i].edge_vertices);
      CHECK(got[i].edge_faces == one[i].edge_faces);
      CHECK(got[i].vertex_edges == one[i].vertex_edges);
      CHECK(got[i].vertex_faces == one[i].vertex_faces);
      CHECK(got[i].vertex_face_corner == one[i].vertex_face_corner);
      CHECK(got[i].vertex_on_boundary == one[i].vertex_on_boundary);
    }
  }
}
