// Face-varying data under the splits whose new faces cross old edges (sqrt3's flipped
// triangles, mid-edge's vertex faces; framework/primvar/crossing_step.h). Every check is a
// property the mathematics gives, not a recorded output:
//  - with no seam the value mesh is the vertex mesh, so the data is refined exactly as the
//    same data carried per vertex (the engine's linearity);
//  - a new point's value is its rule applied in one island: equal to that island refined
//    on its own (where the island's own split makes the same point), and, for rules that
//    are affine combinations with the positions' weights (mid-edge's midpoints, sqrt3's
//    face points), an affine UV map of the island stays exact at the point's position;
//  - a new face inside one island keeps the island's seam structure; an old vertex keeps
//    one value per island around it; mode "all" is linear: old values stay, face points
//    are their face's centroid.
#include <doctest/doctest.h>

#include <array>
#include <functional>
#include <map>
#include <set>

#include "framework/primvar/face_varying.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

using Affine = std::function<std::array<double, 2>(const double* p)>;

// A UV map per island: affine in the position, different for every island.
std::array<double, 2> island_map(int island, const double* p) {
  const double a = 1.0 + 0.5 * island, b = 0.25 * island - 0.5, t = 3.0 * island;
  return {a * p[0] + b * p[1] + 0.1 * p[2] + t, -b * p[0] + a * p[1] - 0.3 * p[2] - t};
}

// A mesh whose faces are sorted into islands: one value per (vertex, island).
struct Seamed {
  Mesh mesh;
  std::vector<int> island;  // per face
  std::vector<double> uv;
  std::vector<Index> indices;
  std::map<std::pair<Index, int>, Index> value_of;  // (vertex, island) -> value
};

Seamed seamed(Mesh mesh, const std::function<int(Index face, const double* centroid)>& island_of) {
  Seamed s{std::move(mesh), {}, {}, {}, {}};
  const Level L = s.mesh.level();
  for (Index f = 0; f < L.face_count(); ++f) {
    double c[3] = {0, 0, 0};
    for (Index v : L.face(f))
      for (int k = 0; k < 3; ++k) c[k] += s.mesh.positions[3 * v + k] / L.face_size(f);
    const int i = island_of(f, c);
    s.island.push_back(i);
    for (Index v : L.face(f)) {
      auto [it, added] = s.value_of.emplace(std::pair(v, i), Index(s.uv.size() / 2));
      if (added) {
        const auto uv = island_map(i, &s.mesh.positions[3 * v]);
        s.uv.insert(s.uv.end(), uv.begin(), uv.end());
      }
      s.indices.push_back(it->second);
    }
  }
  return s;
}

struct Refined {
  Hierarchy h;
  std::vector<FaceVaryingLevel> uv;
};

// The base level, with `crease_seams` every seam edge infinitely sharp.
Level base_level(const Seamed& s, bool crease_seams) {
  Level L = s.mesh.level();
  if (!crease_seams) return L;
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  for (Index e = 0; e < L.edge_count(); ++e)
    if (L.edge_face_count(e) == 2 && s.island[L.edge_faces[2 * e]] != s.island[L.edge_faces[2 * e + 1]])
      L.edge_sharpness[e] = 10.f;
  return L;
}

Refined refine_seamed(const Seamed& s, const std::string& scheme_name, int levels, FaceVaryingLinear mode,
                      bool crease_seams = false) {
  const auto scheme = load_scheme(scheme_name);
  const SchemeRun run{scheme.get(), levels};
  RefineOptions o;
  o.features.boundary = BoundaryInterpolation::EdgesOnly;
  Refined r{refine(std::span(&run, 1), base_level(s, crease_seams), o), {}};
  r.uv = refine_face_varying(std::span(&run, 1), r.h, {s.uv, s.indices}, 2, mode, o);
  return r;
}

// Per-vertex data refined as positions are (stencil tables: another path than the one
// under test): the reference of the no-seam case.
std::vector<double> vertex_refined(const Hierarchy& h, int level, const std::vector<double>& per_vertex) {
  return interpolate(h, level, per_vertex, 2);
}

// With one value per vertex, every face corner's value must be its vertex's, refined as
// positions are.
void check_equals_vertex_refinement(const Mesh& mesh, const std::string& scheme, int levels, FaceVaryingLinear mode) {
  std::vector<double> data;
  for (Index v = 0; v < mesh.vertex_count; ++v) {
    const double* p = &mesh.positions[3 * v];
    data.insert(data.end(), {p[0] * p[0] - p[1] + 0.5 * p[2], std::sin(p[0] + 2 * p[1]) + p[2] * p[2]});
  }
  const Seamed one{mesh, {}, data, std::vector<Index>(mesh.corners.begin(), mesh.corners.end()), {}};
  const Refined r = refine_seamed(one, scheme, levels, mode);
  for (int l = 1; l <= levels; ++l) {
    const std::vector<double> expected = vertex_refined(r.h, l, data);
    const Level& L = r.h.levels[l];
    CHECK(r.uv[l].values.size() == size_t(2 * L.vertex_count));  // no seam appears
    double worst = 0;
    for (size_t c = 0; c < L.face_vertices.size(); ++c)
      for (int k = 0; k < 2; ++k)
        worst = std::max(worst, std::abs(r.uv[l].values[2 * r.uv[l].indices[c] + k] - expected[2 * L.face_vertices[c] + k]));
    CHECK_MESSAGE(worst < 1e-12, scheme, " level ", l, " mode ", face_varying_linear_name(mode), ": ", worst);
  }
}

// The base face each face of level `l` lies in, through the splits' parent faces, or kNone.
Index base_face(const Hierarchy& h, int l, Index f) {
  for (; l > 0 && f != kNone; --l) f = size_t(f) < h.origins[l - 1].parent_face.size() ? h.origins[l - 1].parent_face[f] : kNone;
  return f;
}

// A mid-edge vertex face's corner x takes its value in the old face it shares with the
// preceding corner (both are edges of the base), or, across the outside of a boundary
// vertex, in its edge's only face.
Index face_of_both(const Level& base, Index before, Index x) {
  for (Index f : base.faces_of_edge(x))
    for (Index g : base.faces_of_edge(before))
      if (f == g) return f;
  return base.faces_of_edge(x)[0];
}

// The seam of a 4 x 4 grid of triangles along x = 2, and a closed torus cut around twice.
Seamed seamed_grid(bool triangles) {
  return seamed(grid(4, 4, triangles), [](Index, const double* c) { return c[0] > 2 ? 1 : 0; });
}
Seamed seamed_torus() {
  return seamed(torus(8, 6, true), [](Index, const double* c) { return c[1] > 0 ? 1 : 0; });
}

}  // namespace

TEST_CASE("no seam: face-varying data equals the same data refined per vertex (sqrt3, mid-edge)") {
  using M = FaceVaryingLinear;
  // Open meshes in mode none: the islands' boundary is the mesh's, with the same rules.
  check_equals_vertex_refinement(grid(4, 4, true), "sqrt3", 3, M::None);  // trisected boundary at level 2
  check_equals_vertex_refinement(grid(4, 3), "mid-edge", 3, M::None);
  // Closed meshes have no island boundary: every mode but "all" leaves the data smooth.
  for (M mode : {M::None, M::CornersOnly, M::CornersPlus1, M::CornersPlus2, M::Boundaries}) {
    check_equals_vertex_refinement(torus(6, 4, true), "sqrt3", 3, mode);
    check_equals_vertex_refinement(bipyramid(5), "sqrt3", 2, mode);
    check_equals_vertex_refinement(cube(), "mid-edge", 3, mode);
  }
}

// Island i of `s` refined one sqrt3 step on its own, its UVs as positions: the values of
// its new points, keyed by the base vertex (>= 0) or ~base face (< 0) they come from. The
// first (odd) step flips every interior edge of the island and keeps its boundary, seams
// included, fixed — which is what the step does to the island's points in the whole mesh.
std::map<Index, std::array<double, 2>> island_refined_alone(const Seamed& s, int i) {
  const Level base = s.mesh.level();
  Mesh island;
  std::vector<Index> base_vertex, base_face_of;
  std::map<Index, Index> island_vertex;  // base vertex -> island vertex
  for (Index f = 0; f < base.face_count(); ++f) {
    if (s.island[f] != i) continue;
    for (Index v : base.face(f)) {
      auto [it, added] = island_vertex.emplace(v, island.vertex_count);
      if (added) {
        const Index value = s.value_of.at({v, i});
        island.add_vertex(s.uv[2 * value], s.uv[2 * value + 1], 0);
        base_vertex.push_back(v);
      }
      island.corners.push_back(it->second);
    }
    island.offsets.push_back(Index(island.corners.size()));
    base_face_of.push_back(f);
  }
  RefineOptions io;
  io.features.boundary = BoundaryInterpolation::EdgesOnly;
  io.levels = 1;
  const Hierarchy ih = refine(*load_scheme("sqrt3"), island.level(), io);
  const std::vector<double> ip = interpolate(ih, 1, island.positions, 3);
  std::map<Index, std::array<double, 2>> out;
  for (size_t x = 0; x < ih.origins[0].kind.size(); ++x) {
    const Index p = ih.origins[0].parent[x];
    const Index key = ih.origins[0].kind[x] == OriginKind::Face ? ~base_face_of[p] : base_vertex[p];
    out[key] = {ip[3 * x], ip[3 * x + 1]};
  }
  return out;
}

TEST_CASE("sqrt3 across a seam: every value is its rule in one island, islands keep their values") {
  for (const Seamed& s : {seamed_grid(true), seamed_torus()}) {
    const Refined r = refine_seamed(s, "sqrt3", 1, FaceVaryingLinear::None);
    const Level& base = r.h.levels[0];
    const Level& child = r.h.levels[1];
    const ChildOrigins& o = r.h.origins[0];
    const auto& uv = r.uv[1];
    // One value per old vertex and island around it, one per face point.
    CHECK(uv.values.size() == 2 * (s.value_of.size() + size_t(base.face_count())));
    const std::array<std::map<Index, std::array<double, 2>>, 2> alone{island_refined_alone(s, 0),
                                                                       island_refined_alone(s, 1)};
    std::map<Index, std::set<Index>> values_at_old_vertex;
    std::map<std::pair<Index, int>, Index> value_of_point;  // (point, island) -> value index
    for (Index cf = 0; cf < child.face_count(); ++cf) {
      // The old faces the new face spans: its parent and the faces of its face points.
      std::set<int> spanned{s.island[o.parent_face[cf]]};
      for (Index x : child.face(cf))
        if (o.kind[x] == OriginKind::Face) spanned.insert(s.island[o.parent[x]]);
      for (int k = 0; k < 3; ++k) {
        const Index x = child.face(cf)[k];
        const Index value = uv.indices[size_t(child.face_offsets[cf] + k)];
        const Index key = o.kind[x] == OriginKind::Face ? ~o.parent[x] : o.parent[x];
        int from = -1;  // the island whose own refinement gives this value
        for (int i = 0; i < 2; ++i) {
          const auto it = alone[i].find(key);
          if (it != alone[i].end() && std::abs(it->second[0] - uv.values[2 * value]) < 1e-12 &&
              std::abs(it->second[1] - uv.values[2 * value + 1]) < 1e-12)
            from = i;
        }
        REQUIRE_MESSAGE(from >= 0, "corner ", k, " of new face ", cf, " has a value of no island");
        if (spanned.size() == 1) CHECK(from == *spanned.begin());  // a face inside one island stays in it
        // The documented choice: an old vertex takes its value in the new face's parent face.
        if (o.kind[x] == OriginKind::Vertex) CHECK(from == s.island[o.parent_face[cf]]);
        // One value per point and island: faces inside an island share its values (no new seam).
        auto [it, added] = value_of_point.emplace(std::pair(key, from), value);
        CHECK(it->second == value);
        if (o.kind[x] == OriginKind::Vertex) values_at_old_vertex[o.parent[x]].insert(value);
      }
    }
    // Every old vertex keeps one value per island around it: the seam stays where it was.
    for (Index v = 0; v < base.vertex_count; ++v)
      CHECK_MESSAGE(values_at_old_vertex[v].size() == s.value_of.count({v, 0}) + s.value_of.count({v, 1}),
                    "old vertex ", v);
  }
}

TEST_CASE("sqrt3 in mode all is linear: old values stay, face points are centroids, trisection points thirds") {
  const Seamed s = seamed_grid(true);
  const int levels = 3;
  const Refined r = refine_seamed(s, "sqrt3", levels, FaceVaryingLinear::All);
  for (int l = 1; l <= levels; ++l) {
    const Level& parent = r.h.levels[l - 1];
    const Level& child = r.h.levels[l];
    const ChildOrigins& o = r.h.origins[l - 1];
    const auto &before = r.uv[l - 1], &after = r.uv[l];
    // The parent values of face f at its corners, and of the corner at vertex v.
    auto parent_value = [&](Index f, int corner, int k) {
      return before.values[2 * before.indices[size_t(parent.face_offsets[f] + corner)] + k];
    };
    int checked = 0;
    for (Index cf = 0; cf < child.face_count(); ++cf)
      for (int i = 0; i < 3; ++i) {
        const Index x = child.face(cf)[i];
        const Index value = after.indices[size_t(child.face_offsets[cf] + i)];
        for (int k = 0; k < 2; ++k) {
          const double got = after.values[2 * value + k];
          if (o.kind[x] == OriginKind::Face) {
            const Index f = o.parent[x];
            CHECK(got == doctest::Approx((parent_value(f, 0, k) + parent_value(f, 1, k) + parent_value(f, 2, k)) / 3)
                             .epsilon(1e-13));
          } else if (o.kind[x] == OriginKind::Vertex) {
            // Some face around the old vertex had exactly this value there.
            bool found = false;
            for (int j = 0; j < parent.incident_face_count(o.parent[x]); ++j) {
              const Index f = parent.ring_faces(o.parent[x])[j];
              found = found || parent_value(f, parent.vertex_face_corner[parent.vertex_face_offsets[o.parent[x]] + j], k) == got;
            }
            CHECK(found);
          } else {
            // A trisection point of a boundary edge: a third of the way along one of its faces' sides.
            const Index e = o.parent[x], f = parent.edge_faces[2 * e];
            const auto edges = parent.face_edge_list(f);
            const int slot = int(std::find(edges.begin(), edges.end(), e) - edges.begin());
            const bool forward = parent.face(f)[slot] == parent.edge_vertices[2 * e];
            const double first = parent_value(f, forward ? slot : (slot + 1) % 3, k);
            const double second = parent_value(f, forward ? (slot + 1) % 3 : slot, k);
            const double t = (o.local[x] + 1) / 3.0;
            CHECK(got == doctest::Approx((1 - t) * first + t * second).epsilon(1e-13));
          }
          ++checked;
        }
      }
    CHECK(checked == 2 * int(child.face_vertices.size()));
  }
}

TEST_CASE("mid-edge across seams: affine UV maps stay exact in every island, faces inside one keep its seams") {
  // A quad grid cut along x = 2, and a cube whose six faces are six islands (three values
  // at every vertex).
  const Seamed grid_cut = seamed_grid(false);
  const Seamed cube_unwrapped = seamed(cube(), [](Index f, const double*) { return int(f); });
  for (const Seamed* s : {&grid_cut, &cube_unwrapped})
    for (FaceVaryingLinear mode : {FaceVaryingLinear::None, FaceVaryingLinear::CornersOnly, FaceVaryingLinear::All}) {
      const int levels = 3;
      const Refined r = refine_seamed(*s, "mid-edge", levels, mode);
      const Level& base = r.h.levels[0];
      // One value per edge and side of a seam: the value mesh's edges.
      const Level value_mesh = build_level(Index(s->uv.size() / 2), base.face_offsets, s->indices);
      CHECK(r.uv[1].values.size() == 2 * size_t(value_mesh.edge_count()));
      for (int l = 1; l <= levels; ++l) {
        const Level& L = r.h.levels[l];
        const std::vector<double> positions = interpolate(r.h, l, s->mesh.positions, 3);
        const auto& uv = r.uv[l];
        std::map<std::pair<Index, int>, Index> value_of_point;  // (vertex, island) -> value
        for (Index f = 0; f < L.face_count(); ++f) {
          const Index in_base = base_face(r.h, l, f);
          for (int k = 0; k < L.face_size(f); ++k) {
            const Index x = L.face(f)[k], value = uv.indices[size_t(L.face_offsets[f] + k)];
            // Mid-edge points are edge midpoints, for positions and values alike: every value
            // is an island's affine map at the point's position — at level 1 every one, in
            // the island the rule chose; deeper, those of faces inside one old face.
            std::vector<int> islands;
            if (in_base != kNone) islands = {s->island[in_base]};
            else if (l == 1) {
              const Index before = L.face(f)[(k + L.face_size(f) - 1) % L.face_size(f)];
              const auto& edge_of = r.h.origins[0].parent;  // mid-edge points: one per base edge
              islands = {s->island[face_of_both(base, edge_of[before], edge_of[x])]};
            }
            if (islands.empty()) continue;
            bool matches = false;
            for (int i : islands) {
              const auto expected = island_map(i, &positions[3 * x]);
              const bool same = std::abs(uv.values[2 * value] - expected[0]) < 1e-12 &&
                                std::abs(uv.values[2 * value + 1] - expected[1]) < 1e-12;
              matches = matches || same;
              if (same && in_base != kNone) {
                auto [it, added] = value_of_point.emplace(std::pair(x, i), value);
                CHECK(it->second == value);  // faces inside one island share its values
              }
            }
            CHECK_MESSAGE(matches, "level ", l, " face ", f, " corner ", k);
          }
        }
        // Faces inside different islands never share a value: the seams stay seams.
        std::map<Index, int> island_of_value;
        for (const auto& [point, value] : value_of_point) {
          auto [it, added] = island_of_value.emplace(value, point.second);
          CHECK(it->second == point.second);
        }
      }
    }
}

TEST_CASE("sqrt3 and mid-edge keep the data's shape: counts and indices fit every level") {
  for (const auto& [scheme, s] : {std::pair<std::string, Seamed>{"sqrt3", seamed_grid(true)},
                                  std::pair<std::string, Seamed>{"sqrt3", seamed_torus()},
                                  std::pair<std::string, Seamed>{"mid-edge", seamed_grid(false)}}) {
    const Refined r = refine_seamed(s, scheme, 4, FaceVaryingLinear::CornersOnly);
    for (int l = 0; l <= 4; ++l) {
      CHECK(r.uv[l].indices.size() == r.h.levels[l].face_vertices.size());
      const Index count = Index(r.uv[l].values.size() / 2);
      CHECK(count >= r.h.levels[l].vertex_count);
      for (Index i : r.uv[l].indices) CHECK((i >= 0 && i < count));
      for (double v : r.uv[l].values) CHECK(std::isfinite(v));
    }
  }
}

TEST_CASE("sqrt3 with seams on sharp creases: islands never mix, affine UV maps stay exact at every level") {
  // No new face crosses an infinitely sharp edge, and along the crease the vertex mesh and
  // each island refine the same chain of edges with the same curve rule (trisected in even
  // steps): so every value is its island's affine map at its point's position.
  const Seamed s = seamed_torus();
  const int levels = 4;
  for (FaceVaryingLinear mode : {FaceVaryingLinear::None, FaceVaryingLinear::CornersOnly}) {
    const Refined r = refine_seamed(s, "sqrt3", levels, mode, true);
    for (int l = 1; l <= levels; ++l) {
      const Level& L = r.h.levels[l];
      const std::vector<double> positions = interpolate(r.h, l, s.mesh.positions, 3);
      double worst = 0;
      for (Index f = 0; f < L.face_count(); ++f)
        for (int k = 0; k < 3; ++k) {
          const Index x = L.face(f)[k], value = r.uv[l].indices[size_t(L.face_offsets[f] + k)];
          const auto expected = island_map(s.island[base_face(r.h, l, f)], &positions[3 * x]);
          for (int c = 0; c < 2; ++c) worst = std::max(worst, std::abs(r.uv[l].values[2 * value + c] - expected[c]));
        }
      CHECK_MESSAGE(worst < 1e-11, "level ", l, ": ", worst);
    }
  }
}
