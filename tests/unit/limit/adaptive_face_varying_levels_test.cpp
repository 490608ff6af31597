// Face-varying channels refined with the faces of an adaptive mesh (limit/adaptive_refine.h,
// AdaptiveOptions::face_varying), in every face-varying interpolation mode: each corner's
// value equals the uniform refinement's value of the same corner at the value's level
// (primvar/face_varying.h's refine_face_varying, itself checked against OpenSubdiv's Far in
// tests/unit/primvar/face_varying_osd_test.cpp). A corner is found in the uniform level by
// its base face and its (u, v) there, which the uniform hierarchy's origins give (a child at
// its parent's corner, the middle of its edge, its centre), not by the adaptive code.
// Meshes with seams, a dart, boundaries and extraordinary vertices; Catmull-Clark and Loop;
// feature-adaptive and with a tolerance that splits (nearly) everything.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <limits>
#include <optional>
#include <string_view>
#include <tuple>

#include "framework/features/base_tags.h"
#include "framework/limit/adaptive_refine.h"
#include "framework/limit/limit_surface.h"
#include "framework/primvar/face_varying.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/io/mesh_read.h"
#include "support/cli_runner.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;

namespace {

struct UvMesh {
  test::Mesh mesh;
  std::vector<double> uv;  // 2 per value
  std::vector<Index> indices;
  std::vector<std::tuple<Index, Index, float>> creases;  // (vertex, vertex, sharpness)

  Level level() const {
    Level L = mesh.level();
    L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
    for (const auto& [a, b, s] : creases) L.edge_sharpness[size_t(find_edge(L, a, b))] = s;
    return L;
  }
};

// UVs in islands: faces of one group share a value at a vertex, other groups have their own
// (a seam between groups). Values from the positions and a bump, so no symmetry hides an error.
UvMesh with_islands(test::Mesh m, const std::vector<int>& group) {
  UvMesh out{m, {}, {}, {}};
  const Level L = m.level();
  std::map<std::pair<Index, int>, Index> value_of;
  for (Index f = 0; f < L.face_count(); ++f)
    for (Index v : L.face(f)) {
      const int g = group[size_t(f)];
      auto [it, added] = value_of.emplace(std::pair(v, g), Index(out.uv.size() / 2));
      if (added) {
        const double* x = &m.positions[3 * size_t(v)];
        out.uv.insert(out.uv.end(), {x[0] + 0.1 * x[2] + 0.7 * g + 0.05 * std::sin(1.3 * v),
                                     x[1] + 0.3 * x[2] - 0.2 * g + 0.04 * std::cos(0.7 * v)});
      }
      out.indices.push_back(it->second);
    }
  return out;
}

// Groups by the face's centre: left/right of x = cut, and with `dart` a band above y = 1 on
// the left half (a seam that ends inside the mesh).
std::vector<int> grid_groups(const test::Mesh& m, double cut, bool dart) {
  const Level L = m.level();
  std::vector<int> g;
  for (Index f = 0; f < L.face_count(); ++f) {
    double cx = 0, cy = 0;
    for (Index v : L.face(f)) cx += m.positions[3 * size_t(v)], cy += m.positions[3 * size_t(v) + 1];
    cx /= L.face_size(f), cy /= L.face_size(f);
    g.push_back((cx > cut ? 1 : 0) + (dart && cx < cut && cy > 1 ? 2 : 0));
  }
  return g;
}

using Uv = std::array<double, 2>;
using Key = std::tuple<Index, long long, long long>;  // base face, u and v in units of 2^-12

Key key_of(Index base_face, const Uv& uv) {
  return {base_face, std::llround(uv[0] * 4096), std::llround(uv[1] * 4096)};
}

// Per uniform level: each face's base face and corners' (u, v) (quads (0,0) (1,0) (1,1) (0,1),
// triangles (0,0) (1,0) (0,1)), from the hierarchy's origins.
struct UniformCorners {
  std::vector<Index> base_face;
  std::vector<Uv> uv;  // per face corner; NaN on a base n-gon of a quad split (it has sub-faces)
};

// Bfr's QUAD_SUBFACES (Bfr::Parameterization, OpenSubdiv 3.5): an n-gon's sub-face k (the
// child at its vertex k) is the square [c, c + 1/2] x [r, r + 1/2], column c = k mod w and row
// r = k / w on a grid of w = ceil(sqrt(n)) columns; its corner at vertex k is (c, r), the
// middle of edge k (to vertex k + 1) (c + 1/2, r), the centre (c + 1/2, r + 1/2), the middle of
// edge k - 1 (c, r + 1/2).
std::vector<Uv> sub_face_corners(const Level& P, Index f, const Level& C, Index g, const ChildOrigins& o) {
  const auto fv = P.face(f);
  const int n = int(fv.size());
  const int columns = int(std::ceil(std::sqrt(double(n)) - 1e-12));
  int k = -1;
  for (Index c : C.face(g))
    if (o.kind[size_t(c)] == OriginKind::Vertex)
      for (int i = 0; i < n; ++i)
        if (fv[size_t(i)] == o.parent[size_t(c)]) k = i;
  REQUIRE(k >= 0);
  const double col = k % columns, row = k / columns;
  const Index next = fv[size_t((k + 1) % n)];
  std::vector<Uv> out;
  for (Index c : C.face(g)) {
    const Index from = o.parent[size_t(c)];
    if (o.kind[size_t(c)] == OriginKind::Vertex) {
      out.push_back({col, row});
    } else if (o.kind[size_t(c)] == OriginKind::Face) {
      out.push_back({col + 0.5, row + 0.5});
    } else {
      const bool towards_next =
          P.edge_vertices[size_t(2 * from)] == next || P.edge_vertices[size_t(2 * from + 1)] == next;
      out.push_back(towards_next ? Uv{col + 0.5, row} : Uv{col, row + 0.5});
    }
  }
  return out;
}

std::vector<UniformCorners> uniform_corners(const Hierarchy& h, bool triangles) {
  std::vector<UniformCorners> out(h.levels.size());
  const Level& B = h.levels[0];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (Index f = 0; f < B.face_count(); ++f) {
    out[0].base_face.push_back(f);
    const std::vector<Uv> corners = B.face_size(f) == 3 && triangles ? std::vector<Uv>{{0, 0}, {1, 0}, {0, 1}}
                                    : B.face_size(f) == 4 ? std::vector<Uv>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}
                                                          : std::vector<Uv>(size_t(B.face_size(f)), Uv{nan, nan});
    out[0].uv.insert(out[0].uv.end(), corners.begin(), corners.end());
  }
  for (size_t l = 0; l + 1 < h.levels.size(); ++l) {
    const Level &P = h.levels[l], &C = h.levels[l + 1];
    const ChildOrigins& o = h.origins[l];
    for (Index g = 0; g < C.face_count(); ++g) {
      const Index f = o.parent_face[size_t(g)];
      out[l + 1].base_face.push_back(out[l].base_face[size_t(f)]);
      if (l == 0 && std::isnan(out[0].uv[size_t(P.face_offsets[size_t(f)])][0])) {
        const std::vector<Uv> corners = sub_face_corners(P, f, C, g, o);
        out[1].uv.insert(out[1].uv.end(), corners.begin(), corners.end());
        continue;
      }
      const auto fv = P.face(f);
      const Uv* fuv = out[l].uv.data() + P.face_offsets[size_t(f)];
      auto uv_of = [&](Index v) {
        for (size_t k = 0; k < fv.size(); ++k)
          if (fv[k] == v) return fuv[k];
        FAIL("a child's parent vertex is not a corner of its parent face");
        return Uv{};
      };
      for (Index c : C.face(g)) {
        const Index from = o.parent[size_t(c)];
        Uv uv{0, 0};
        if (o.kind[size_t(c)] == OriginKind::Vertex) {
          uv = uv_of(from);
        } else if (o.kind[size_t(c)] == OriginKind::Edge) {
          const Uv a = uv_of(P.edge_vertices[size_t(2 * from)]), b = uv_of(P.edge_vertices[size_t(2 * from + 1)]);
          uv = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
        } else {
          const double n = double(fv.size());
          for (size_t k = 0; k < fv.size(); ++k) uv[0] += fuv[k][0] / n, uv[1] += fuv[k][1] / n;
        }
        out[l + 1].uv.push_back(uv);
      }
    }
  }
  return out;
}

struct Compared {
  double worst = 0;
  size_t corners = 0, missing = 0, along_edges = 0;  // along_edges: transition polygons' extra corners
  int finest = 0, coarsest = 99;  // the levels values came from
};

Compared compare(const UvMesh& m, const char* scheme_name, FaceVaryingLinear mode, int levels, double tolerance,
                 BoundaryInterpolation boundary) {
  const auto scheme = load_scheme(scheme_name);
  const Level base = m.level();
  const SchemeRun run{scheme.get(), levels};
  RefineOptions ro;
  ro.levels = levels;
  ro.features.boundary = boundary;
  const Hierarchy h = refine_topology(std::span(&run, 1), base, ro);
  const auto uniform = refine_face_varying(std::span(&run, 1), h, {m.uv, m.indices}, 2, mode, ro);
  const std::vector<UniformCorners> corners = uniform_corners(h, std::string_view(scheme_name) == "loop");
  std::vector<std::map<Key, Uv>> reference(h.levels.size());
  for (size_t l = 0; l < h.levels.size(); ++l)
    for (size_t c = 0; c < corners[l].uv.size(); ++c) {
      const Index f = Index(std::upper_bound(h.levels[l].face_offsets.begin(), h.levels[l].face_offsets.end(),
                                             Index(c)) - h.levels[l].face_offsets.begin()) - 1;
      if (std::isnan(corners[l].uv[c][0])) continue;  // a base n-gon's corner: its sub-faces hold the points
      const Index value = uniform[l].indices[c];
      reference[l][key_of(corners[l].base_face[size_t(f)], corners[l].uv[c])] =
          Uv{uniform[l].values[2 * size_t(value)], uniform[l].values[2 * size_t(value) + 1]};
    }

  // The value mesh over the base with the tags refinement gives it first (boundary corners),
  // as the pipeline builds it.
  Level tagged = base;
  tag_boundary_holes(tagged, boundary);
  tag_boundary_corners(tagged, boundary);
  const FaceVaryingValueMesh values = face_varying_value_mesh(tagged, {m.uv, m.indices}, 2, mode, boundary);
  const AdaptiveValueMesh channel{&values.level, values.values.values, 2, mode == FaceVaryingLinear::Boundaries,
                                  mode == FaceVaryingLinear::All};
  std::optional<LimitSurface> surface;
  AdaptiveOptions o;
  o.levels = levels;
  o.features.boundary = boundary;
  o.face_varying = std::span(&channel, 1);
  if (tolerance > 0) o.tolerance = tolerance, o.surface = &surface.emplace(scheme, base);
  const AdaptiveMesh a = refine_adaptive(*scheme, base, m.mesh.positions, o);
  REQUIRE(a.face_varying.size() == 1);
  const AdaptiveFaceVarying& fv = a.face_varying[0];
  REQUIRE(fv.indices.size() == a.face_vertices.size());
  Compared out;
  for (size_t f = 0; f + 1 < a.face_offsets.size(); ++f)
    for (Index c = a.face_offsets[f]; c < a.face_offsets[f + 1]; ++c) {
      const Index value = fv.indices[size_t(c)];
      const int l = fv.value_level[size_t(value)];
      out.finest = std::max(out.finest, l), out.coarsest = std::min(out.coarsest, l);
      CHECK(l >= a.face_level[f]);  // a face's corners exist from its level on
      const auto it = reference[size_t(l)].find(key_of(a.base_face[f], a.corner_uv[size_t(c)]));
      if (it == reference[size_t(l)].end()) {
        ++out.missing;
        continue;
      }
      ++out.corners;
      out.along_edges += a.corner_is_face_corner[size_t(c)] == 0;
      for (int k = 0; k < 2; ++k)
        out.worst = std::max(out.worst, std::abs(fv.values[2 * size_t(value) + size_t(k)] - it->second[size_t(k)]));
    }
  return out;
}

const FaceVaryingLinear kModes[] = {FaceVaryingLinear::None,         FaceVaryingLinear::CornersOnly,
                                    FaceVaryingLinear::CornersPlus1, FaceVaryingLinear::CornersPlus2,
                                    FaceVaryingLinear::Boundaries,   FaceVaryingLinear::All};

void check_every_mode(const UvMesh& m, const std::string& scheme, int levels, double tolerance, const std::string& what,
                      BoundaryInterpolation boundary = BoundaryInterpolation::EdgesAndCorners) {
  for (FaceVaryingLinear mode : kModes) {
    const std::string mode_name = face_varying_linear_name(mode);
    CAPTURE(mode_name);
    CAPTURE(tolerance);
    const Compared c = compare(m, scheme.c_str(), mode, levels, tolerance, boundary);
    MESSAGE(what, ", ", scheme, ", mode ", mode_name, ", tolerance ", tolerance, ": ", c.corners, " corners (",
            c.along_edges, " along edges; values from levels ", c.coarsest, " to ", c.finest,
            "), largest difference from uniform ",
            c.worst);
    CHECK(c.missing == 0);
    CHECK(c.corners > 0);
    CHECK(c.finest == levels);
    // Round-off relative to the values' size (with_islands shifts each island by 0.7: the car's
    // 1575 islands reach about 1100).
    double size = 1;
    for (double x : m.uv) size = std::max(size, std::abs(x));
    CHECK(c.worst < 1e-14 * size);
  }
}

}  // namespace

TEST_CASE("Adaptive Catmull-Clark carries UVs with seams in every mode: a level's values, as uniform refinement's") {
  // The cube: two faces in one island, the others alone (valence-3 vertices on seams).
  const UvMesh cube = with_islands(limit_test::bumped(test::cube()), {0, 0, 1, 2, 3, 4});
  // An open grid (boundaries, boundary corners) cut by a seam, with a dart, and a crease
  // ending inside: sharp, then semi-sharp (what the feature-adaptive refinement isolates).
  const test::Mesh g = limit_test::bumped(test::grid(5, 4));
  UvMesh grid = with_islands(g, grid_groups(g, 2.5, true));
  grid.creases = {{7, 8, 10.f}, {8, 9, 1.5f}};
  // A regular torus with a band of faces along a meridian and one along a parallel in UV
  // islands of their own (seams, and vertices where three islands meet), refined everywhere
  // with a tolerance (nothing is irregular).
  const test::Mesh t = limit_test::bumped(test::torus(6, 4));
  std::vector<int> torus_groups;
  for (Index f = 0; f < t.level().face_count(); ++f)
    torus_groups.push_back((f % 6 == 5 ? 1 : 0) + (f / 6 == 2 ? 2 : 0));
  const UvMesh torus = with_islands(t, torus_groups);
  check_every_mode(cube, "catmull-clark", 3, 0, "cube");
  check_every_mode(cube, "catmull-clark", 2, 1e-300, "cube");
  check_every_mode(grid, "catmull-clark", 3, 0, "grid");
  check_every_mode(grid, "catmull-clark", 2, 1e-300, "grid");
  check_every_mode(grid, "catmull-clark", 3, 0, "grid, boundary rule edges", BoundaryInterpolation::EdgesOnly);
  check_every_mode(grid, "catmull-clark", 3, 0, "grid, boundary rule none", BoundaryInterpolation::None);
  check_every_mode(torus, "catmull-clark", 2, 1e-300, "torus");
}

TEST_CASE("Adaptive Catmull-Clark carries UVs on faces other than quads (Bfr's sub-faces)") {
  // Triangles and a hexagon under Catmull-Clark: each is split into sub-quads at level 1,
  // whose corners the reference places by Bfr's QUAD_SUBFACES layout (sub_face_corners).
  // The pyramid: four triangles and a quad, a seam between two islands of triangles.
  const UvMesh pyramid = with_islands(limit_test::bumped(test::pyramid()), {0, 1, 1, 2, 2});
  // A 5 x 4 grid with two quads merged into a hexagon (its two middle vertices interior of
  // valence 3), cut by a seam and a dart band that runs through the hexagon.
  test::Mesh g;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 5; ++i) g.add_vertex(i, j, 0);
  auto id = [](int i, int j) { return Index(j * 6 + i); };
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 5; ++i)
      if (j != 1 || (i != 1 && i != 2)) g.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  g.add_face({id(1, 1), id(2, 1), id(3, 1), id(3, 2), id(2, 2), id(1, 2)});
  g = limit_test::bumped(g);
  UvMesh hexagon = with_islands(g, grid_groups(g, 2.5, true));
  hexagon.creases = {{id(3, 1), id(3, 2), 2.5f}};
  check_every_mode(pyramid, "catmull-clark", 3, 0, "pyramid");
  check_every_mode(pyramid, "catmull-clark", 2, 1e-300, "pyramid");
  check_every_mode(hexagon, "catmull-clark", 3, 0, "grid with a hexagon");
  check_every_mode(hexagon, "catmull-clark", 2, 1e-300, "grid with a hexagon");
}

TEST_CASE("Adaptive Catmull-Clark carries UVs with a seam at every edge where the stages fill pinches") {
  // OpenSubdiv's car: the vertex stages keep a few children of ghost faces (where the kept
  // faces would pinch a vertex), which the channel's stages take over; every face its own
  // UV island.
  const MeshData car = read_mesh(test::source_path("tests/data/osd-shapes/catmark_car.obj"));
  test::Mesh m;
  m.vertex_count = Index(car.positions.size() / 3);
  m.positions = car.positions;
  m.offsets.assign(car.face_offsets.begin(), car.face_offsets.end());
  m.corners.assign(car.face_vertices.begin(), car.face_vertices.end());
  std::vector<int> own_island(m.offsets.size() - 1);
  std::iota(own_island.begin(), own_island.end(), 0);
  check_every_mode(with_islands(m, own_island), "catmull-clark", 2, 0, "car");
}

TEST_CASE("Adaptive Loop carries UVs with seams in every mode: a level's values, as uniform refinement's") {
  const UvMesh octahedron = with_islands(limit_test::bumped(limit_test::octahedron()), {0, 0, 0, 1, 1, 2, 2, 2});
  const test::Mesh g = limit_test::bumped(test::grid(5, 4, true));
  UvMesh grid = with_islands(g, grid_groups(g, 2.5, true));
  grid.creases = {{7, 8, 10.f}, {8, 9, 1.5f}};
  check_every_mode(octahedron, "loop", 3, 0, "octahedron");
  check_every_mode(octahedron, "loop", 2, 1e-300, "octahedron");
  check_every_mode(grid, "loop", 3, 0, "triangulated grid");
  check_every_mode(grid, "loop", 2, 1e-300, "triangulated grid");
}
