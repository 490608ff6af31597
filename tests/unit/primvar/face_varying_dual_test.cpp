// Face-varying data under a dual split (framework/primvar/face_varying.cpp): every new point
// is a face corner, and its value must be what the dual scheme gives that corner in its own
// UV island — the island refined on its own, with its UVs as coordinates.
#include <doctest/doctest.h>

#include <map>

#include "framework/primvar/face_varying.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"

using namespace subdiv;
using namespace subdiv::test;

TEST_CASE("Doo-Sabin: each new point's UV is the dual rule applied in its own island") {
  // A 4 x 3 grid cut along x = 2 in UV space: the left island keeps (x, y), the right one
  // gets (x + 0.5 + 0.1 y^2, y) (not affine, so that rules matter).
  const Mesh mesh = grid(4, 3);
  const Level base = mesh.level();
  std::vector<double> uv;
  std::vector<Index> indices;
  std::map<std::pair<Index, int>, Index> value_of;
  std::vector<int> side_of(size_t(base.face_count()));
  for (Index f = 0; f < base.face_count(); ++f) {
    double cx = 0;
    for (Index v : base.face(f)) cx += mesh.positions[3 * v];
    side_of[f] = cx / base.face_size(f) > 2 ? 1 : 0;
    for (Index v : base.face(f)) {
      auto [it, added] = value_of.emplace(std::pair(v, side_of[f]), Index(uv.size() / 2));
      const double x = mesh.positions[3 * v], y = mesh.positions[3 * v + 1];
      if (added) uv.insert(uv.end(), {side_of[f] ? x + 0.5 + 0.1 * y * y : x, y});
      indices.push_back(it->second);
    }
  }
  const auto scheme = load_scheme("doo-sabin");
  const SchemeRun run{scheme.get(), 1};
  RefineOptions o;
  const Hierarchy h = refine_topology(std::span(&run, 1), base, o);
  const auto levels = refine_face_varying(std::span(&run, 1), h, {uv, indices}, 2, FaceVaryingLinear::None, o);
  REQUIRE(levels.size() == 2);
  const Level& child = h.levels[1];
  // One value per new point at level 1: read it at any corner that uses the point.
  std::vector<Index> value_at(size_t(child.vertex_count), kNone);
  for (size_t c = 0; c < child.face_vertices.size(); ++c) {
    Index& at = value_at[child.face_vertices[c]];
    CHECK((at == kNone || at == levels[1].indices[c]));
    at = levels[1].indices[c];
  }
  int checked = 0;
  for (int side = 0; side < 2; ++side) {
    // The island as a mesh of its own, its UVs as positions.
    Mesh island;
    std::map<Index, Index> island_vertex;  // value -> island vertex
    std::vector<Index> island_face_of;      // island face -> grid face
    for (Index f = 0; f < base.face_count(); ++f) {
      if (side_of[f] != side) continue;
      std::vector<Index> corners;
      for (int k = 0; k < base.face_size(f); ++k) {
        const Index value = indices[size_t(base.face_offsets[f] + k)];
        auto [it, added] = island_vertex.emplace(value, island.vertex_count);
        if (added) island.add_vertex(uv[2 * value], uv[2 * value + 1], 0);
        corners.push_back(it->second);
      }
      island.corners.insert(island.corners.end(), corners.begin(), corners.end());
      island.offsets.push_back(Index(island.corners.size()));
      island_face_of.push_back(f);
    }
    RefineOptions io;
    io.features.boundary = BoundaryInterpolation::EdgesOnly;  // the seam is the island's boundary, a smooth one
    io.levels = 1;
    const Hierarchy ih = refine(*scheme, island.level(), io);
    const std::vector<double> ip = interpolate(ih, 1, island.positions, 3);
    for (size_t c = 0; c < ih.origins[0].kind.size(); ++c) {
      const Index grid_face = island_face_of[ih.origins[0].parent[c]];
      const int corner = ih.origins[0].local[c];
      // Our new point of the same face corner.
      Index ours = kNone;
      for (Index v = 0; v < child.vertex_count; ++v)
        if (h.origins[0].parent[v] == grid_face && h.origins[0].local[v] == corner) ours = v;
      REQUIRE(ours != kNone);
      const Index value = value_at[ours];
      CHECK(levels[1].values[2 * value] == doctest::Approx(ip[3 * c]).epsilon(1e-14));
      CHECK(levels[1].values[2 * value + 1] == doctest::Approx(ip[3 * c + 1]).epsilon(1e-14));
      ++checked;
    }
  }
  CHECK(checked == base.corner_count());
}
