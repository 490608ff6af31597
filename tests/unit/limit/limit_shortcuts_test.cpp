// The shortcuts of limit evaluation (LimitSurfaceOptions::shortcuts): faces in untagged
// regular quad grid share one node without cutting and signing their neighbourhoods, and
// points in bicubic faces skip the descent. They must give the very bits the general way
// gives, and be taken only where a face's whole cut is such grid (quad_grid_labelled).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <span>
#include <utility>
#include <tuple>

#include "framework/analysis/surface/local_patch.h"
#include "framework/features/sharpness.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/limit/same_bits.h"

using namespace subdiv;

namespace {

constexpr int kRadius = 4;  // the cut Catmull-Clark's evaluation takes (limit_surface.cpp)

// The surface of the box [0, n]^3 without its top, in n x n quads per side, outward CCW:
// valence-3 vertices at the four bottom corners, a boundary along the top rim, and
// regular grid in the middle of every side.
test::Mesh open_box(int n) {
  test::Mesh m;
  std::map<std::tuple<int, int, int>, Index> id;
  auto vertex = [&](std::array<int, 3> p) {
    const auto key = std::make_tuple(p[0], p[1], p[2]);
    const auto it = id.find(key);
    if (it != id.end()) return it->second;
    // A bump, so that no two evaluated points agree by symmetry alone.
    m.add_vertex(p[0], p[1], p[2] + 0.05 * std::sin(1.3 * p[0] + 0.7 * p[1] + 0.4 * p[2]));
    return id[key] = m.vertex_count - 1;
  };
  // Per side: its base point and two tangents t1, t2 with t1 x t2 the outward normal.
  struct Side {
    std::array<int, 3> base, t1, t2;
  };
  const Side sides[] = {{{n, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                        {{0, n, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
                        {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}};
  for (const Side& s : sides)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        auto at = [&](int a, int b) {
          std::array<int, 3> p{};
          for (size_t k = 0; k < 3; ++k) p[k] = s.base[k] + a * s.t1[k] + b * s.t2[k];
          return vertex(p);
        };
        m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  return m;
}

// Face-ring distances from the vertices `from` (the "shares a face" metric the cut uses).
std::vector<int> distances(const Level& L, const std::vector<Index>& from) {
  std::vector<int> d(size_t(L.vertex_count), 1 << 20);
  std::vector<Index> queue;
  for (Index v : from)
    if (d[size_t(v)] != 0) d[size_t(v)] = 0, queue.push_back(v);
  for (size_t q = 0; q < queue.size(); ++q)
    for (Index f : L.ring_faces(queue[q]))
      for (Index w : L.face(f))
        if (d[size_t(w)] > d[size_t(queue[q])] + 1) d[size_t(w)] = d[size_t(queue[q])] + 1, queue.push_back(w);
  return d;
}

int face_distance(const Level& L, const std::vector<int>& d, Index f) {
  int best = 1 << 20;
  for (Index v : L.face(f)) best = std::min(best, d[size_t(v)]);
  return best;
}

// The box with a tagged crease down one vertical edge, a semi-sharp crease on a side and a
// tagged corner on the bottom: the sharp edges' ends in `ends`, the corner in `corners`.
Level tagged_box(int n, std::vector<Index>& ends, std::vector<Index>& corners) {
  const test::Mesh m = open_box(n);
  Level L = m.level();
  L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
  L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
  // Vertex ids of open_box's first side (x = n): (n, i, j) at the order they were made.
  auto near = [&](double x, double y, double z) {
    Index best = 0;
    double dist = 1e300;
    for (Index v = 0; v < Index(m.vertex_count); ++v) {
      const double dx = m.positions[size_t(3 * v)] - x, dy = m.positions[size_t(3 * v + 1)] - y;
      const double dz = std::round(m.positions[size_t(3 * v + 2)]) - z;
      if (dx * dx + dy * dy + dz * dz < dist) dist = dx * dx + dy * dy + dz * dz, best = v;
    }
    return best;
  };
  auto sharpen = [&](Index a, Index b, float s) {
    L.edge_sharpness[size_t(find_edge(L, a, b))] = s;
    ends.push_back(a), ends.push_back(b);
  };
  for (int z = 0; z < n; ++z) sharpen(near(n, n, z), near(n, n, z + 1), kInfinitelySharp);  // a vertical box edge
  for (int y = 3; y < 7; ++y) sharpen(near(n, y, n / 2), near(n, y + 1, n / 2), 1.5f);       // semi-sharp on x = n
  const Index corner = near(n / 2, n / 2, 0);                                               // bottom middle
  L.vertex_sharpness[size_t(corner)] = kInfinitelySharp;
  corners.push_back(corner);
  return L;
}

// Every triangle of `t` split into three quads at its centroid and edge midpoints: on a
// triangulated torus an extraordinary vertex in every quad (valences 3 and 6), in a pattern
// that repeats, so that most faces take their entries from the pieces of faces met before.
test::Mesh split_into_quads(const test::Mesh& t) {
  test::Mesh m;
  for (Index v = 0; v < Index(t.vertex_count); ++v)
    m.add_vertex(t.positions[size_t(3 * v)], t.positions[size_t(3 * v + 1)], t.positions[size_t(3 * v + 2)]);
  std::map<std::pair<Index, Index>, Index> mids;
  auto point = [&](std::initializer_list<Index> of) {
    double x[3] = {0, 0, 0};
    for (Index v : of)
      for (size_t d = 0; d < 3; ++d) x[d] += t.positions[size_t(3 * v) + d] / double(of.size());
    m.add_vertex(x[0], x[1], x[2] + 0.03 * std::sin(2.1 * x[0] + 1.3 * x[1]));
    return Index(m.vertex_count - 1);
  };
  auto mid = [&](Index a, Index b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    const auto it = mids.find(key);
    return it != mids.end() ? it->second : mids[key] = point({a, b});
  };
  for (size_t f = 0; f + 1 < t.offsets.size(); ++f) {
    const Index* c = &t.corners[size_t(t.offsets[f])];
    const Index centre = point({c[0], c[1], c[2]});
    for (int k = 0; k < 3; ++k)
      m.add_face({c[k], mid(c[k], c[(k + 1) % 3]), centre, mid(c[(k + 2) % 3], c[k])});
  }
  return m;
}

// Catmull-Clark with and without the shortcuts at a random point of every face, in the
// faces' order (so that what earlier faces prepared serves later ones): positions and first
// derivatives alike, and every `full`-th face through check_same_bits (stencils included).
void check_every_face(const Level& base, std::span<const double> positions, unsigned seed, Index full) {
  LimitSurfaceOptions general;
  general.shortcuts = false;
  const LimitSurface a(load_scheme("catmull-clark"), base), b(load_scheme("catmull-clark"), base, general);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  for (Index f = 0; f < base.face_count(); ++f) {
    const double u = unit(rng), v = unit(rng);
    INFO("face " << f << " at (" << u << ", " << v << ")");
    if (f % full == 0)
      limit_test::check_same_bits(a, b, f, u, v, positions, 1);
    else
      limit_test::check_same_sample(a.evaluate(f, u, v, positions, 3, 1), b.evaluate(f, u, v, positions, 3, 1));
  }
}

}  // namespace

TEST_CASE("quad_grid_labelled: a torus is grid exactly when the neighbourhood does not wrap around") {
  // The cut of radius 4 around a quad spans 10 x 10 vertices: a narrower torus meets itself.
  for (const auto& size : {std::array<int, 2>{10, 10}, {10, 12}, {9, 12}, {12, 9}, {6, 30}}) {
    const Level L = test::torus(size[0], size[1]).level();
    const bool wide = size[0] >= 2 * kRadius + 2 && size[1] >= 2 * kRadius + 2;
    Labelling lab;
    for (Index f = 0; f < L.face_count(); ++f) {
      INFO("torus " << size[0] << " x " << size[1] << ", face " << f);
      CHECK(quad_grid_labelled(lab, L, f, kRadius) == wide);
    }
  }
}

TEST_CASE("quad_grid_distances: quad_grid_labelled's answer, vertices and distances, in any order within a ring") {
  // (vertex, distance) pairs of a labelling, sorted: the same set whatever the order of labels.
  auto pairs = [](const Labelling& lab) {
    std::vector<std::pair<Index, int>> p;
    for (size_t q = 0; q < lab.vertices.size(); ++q) p.emplace_back(lab.vertices[q], lab.distance[q]);
    std::sort(p.begin(), p.end());
    return p;
  };
  std::vector<Index> ends, corners;
  std::vector<Level> levels{tagged_box(14, ends, corners)};
  for (const auto& size : {std::array<int, 2>{9, 12}, {22, 22}, {30, 41}}) levels.push_back(test::torus(size[0], size[1]).level());
  for (int valence : {3, 5}) {
    LocalConfig c;
    c.valence = valence;
    levels.push_back(make_vertex_patch(PatchCells::Quads, c, 14).level);
  }
  int grid = 0;
  for (const Level& L : levels)
    for (int radius : {kRadius, kRadius + 4}) {
      Labelling a, b;
      for (Index f = 0; f < L.face_count(); ++f) {
        INFO("level of " << L.face_count() << " faces, face " << f << ", radius " << radius);
        const bool labelled = quad_grid_labelled(a, L, f, radius);
        REQUIRE(quad_grid_distances(b, L, f, radius) == labelled);
        if (!labelled) continue;
        ++grid;
        CHECK(std::is_sorted(b.distance.begin(), b.distance.end()));
        CHECK(pairs(a) == pairs(b));
      }
    }
  CHECK(grid > 100);
}

TEST_CASE("quad_grid_labelled is never true with an irregular vertex, a boundary or a tag within the cut") {
  SUBCASE("valence 3 and 5 vertices, each the only irregular vertex of a grid") {
    for (int valence : {3, 5}) {
      LocalConfig c;
      c.valence = valence;
      const Patch p = make_vertex_patch(PatchCells::Quads, c, 14);
      const Level& L = p.level;
      std::vector<Index> rim;
      for (Index v = 0; v < L.vertex_count; ++v)
        if (L.on_boundary(v)) rim.push_back(v);
      const std::vector<int> to_centre = distances(L, {p.centre}), to_rim = distances(L, rim);
      int grid = 0;
      Labelling lab;
      for (Index f = 0; f < L.face_count(); ++f) {
        const int a = face_distance(L, to_centre, f), b = face_distance(L, to_rim, f);
        const bool result = quad_grid_labelled(lab, L, f, kRadius);
        INFO("valence " << valence << ", face " << f << " at " << a << " rings from the centre, " << b
                        << " from the boundary");
        // The cut's vertices closer than the radius must all be regular interior ones.
        if (a < kRadius || b < kRadius) CHECK_FALSE(result);
        if (a > kRadius && b > kRadius) CHECK(result);
        grid += result ? 1 : 0;
      }
      CHECK(grid > 0);
    }
  }
  SUBCASE("a tagged crease, a semi-sharp crease and a tagged corner, whatever their distance in the cut") {
    std::vector<Index> ends, corners;
    const Level L = tagged_box(14, ends, corners);
    const std::vector<int> to_edge = distances(L, ends), to_corner = distances(L, corners);
    Labelling lab;
    int grid = 0;
    for (Index f = 0; f < L.face_count(); ++f) {
      const int a = face_distance(L, to_edge, f), b = face_distance(L, to_corner, f);
      INFO("face " << f << " at " << a << " rings from a sharp edge, " << b << " from the tagged corner");
      // The cut holds every face of a vertex closer than kRadius, so every edge at such a
      // vertex, and every vertex within kRadius.
      const bool result = quad_grid_labelled(lab, L, f, kRadius);
      if (a < kRadius || b <= kRadius) CHECK_FALSE(result);
      grid += result ? 1 : 0;
    }
    CHECK(grid > 0);
  }
}

TEST_CASE("The shortcuts give the general way's bits on a mesh mixing grid, irregular, boundary and tagged faces") {
  std::vector<Index> ends, corners;
  const Level base = tagged_box(14, ends, corners);
  const test::Mesh m = open_box(14);
  LimitSurfaceOptions general;
  general.shortcuts = false;
  for (auto boundary : {BoundaryInterpolation::EdgesAndCorners, BoundaryInterpolation::EdgesOnly}) {
    LimitSurfaceOptions fast;
    fast.features.boundary = general.features.boundary = boundary;
    const LimitSurface a(load_scheme("catmull-clark"), base, fast), b(load_scheme("catmull-clark"), base, general);
    int grid = 0;
    Labelling lab;
    for (Index f = 0; f < base.face_count(); ++f) grid += quad_grid_labelled(lab, base, f, kRadius) ? 1 : 0;
    CHECK(grid > 100);  // the shortcut is taken, not only allowed
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    for (Index f = 0; f < base.face_count(); ++f)
      for (int k = 0; k < 3; ++k) {
        // Corners and edges too: the general way ends at a corner's masks there only if the
        // face's node is not the bicubic patch.
        const double u = k == 0 ? 0.0 : unit(rng), v = k == 1 ? 1.0 : unit(rng);
        INFO("face " << f << " at (" << u << ", " << v << ")");
        limit_test::check_same_bits(a, b, f, u, v, m.positions, 2);
      }
  }
}

TEST_CASE("The shortcuts give the general way's bits on grid wide enough that faces are known grid in pieces") {
  // A torus wider than the piece checked at once around a face (the cut's radius and a
  // margin of 8 rings: 26 x 26 vertices), so that faces near it are marked and read their
  // control points without labelling (first_grid_labels); a semi-sharp edge leaves some
  // faces out.
  const test::Mesh m = test::torus(48, 44);
  Level base = m.level();
  base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
  base.edge_sharpness[size_t(find_edge(base, 10, 11))] = 1.5f;
  check_every_face(base, m.positions, 13, 37);
}

TEST_CASE("The shortcuts give the general way's bits whether grid is checked in wide or narrow pieces") {
  // Pieces are checked 16 rings wider than the cut (42 x 42 vertices) until one fails, then
  // 8 rings wider (26 x 26): untagged tori where every wide piece passes (48 x 44), where the
  // wide pieces wrap round and the narrow ones pass (32 x 30), and where both wrap (20 x 20:
  // each face checks its own cut).
  for (const auto& size : {std::array<int, 2>{48, 44}, {32, 30}, {20, 20}}) {
    INFO("torus " << size[0] << " x " << size[1]);
    const test::Mesh m = test::torus(size[0], size[1]);
    check_every_face(m.level(), m.positions, 17, 29);
  }
}

TEST_CASE("The shortcuts give the general way's bits where faces take their entries from pieces met before") {
  // An extraordinary vertex in every face, in a repeating pattern: on a torus, untagged and
  // with a crease, a semi-sharp edge and a tagged corner in one corner of its parameter
  // square (faces whose wide keys differ near the tags while their own cuts are the far
  // faces'); on a grid, with its boundary.
  const test::Mesh small = split_into_quads(test::torus(12, 10, true)), large = split_into_quads(test::torus(20, 18, true));
  const test::Mesh grid = split_into_quads(test::grid(16, 16, true));
  for (int variant = 0; variant < 3; ++variant) {
    const test::Mesh& m = variant == 0 ? small : variant == 1 ? large : grid;
    Level base = m.level();
    if (variant == 1) {
      base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
      base.vertex_sharpness.assign(size_t(base.vertex_count), 0.f);
      for (Index f = 0; f < 6; ++f) {  // a crease along the first faces' first edges
        const auto c = base.face(f);
        base.edge_sharpness[size_t(find_edge(base, c[0], c[1]))] = kInfinitelySharp;
      }
      const auto near = base.face(20);
      base.edge_sharpness[size_t(find_edge(base, near[1], near[2]))] = 1.5f;
      base.vertex_sharpness[size_t(base.face(40)[2])] = kInfinitelySharp;
    }
    INFO("variant " << variant);
    check_every_face(base, m.positions, 11, 9);
  }
}

TEST_CASE("The shortcuts give the general way's bits for Loop: regular triangles, a boundary, creases") {
  // The polynomial-patch shortcut (a node's quartic triangle patch taken from its entry).
  for (const test::Mesh& m : {test::torus(12, 12, true), test::grid(10, 10, true), test::bipyramid(5)}) {
    Level base = m.level();
    if (m.vertex_count == 121) {  // the grid: a sharp crease across it, a semi-sharp edge
      base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
      for (Index i = 0; i < 10; ++i) base.edge_sharpness[size_t(find_edge(base, 55 + i, 56 + i))] = kInfinitelySharp;
      base.edge_sharpness[size_t(find_edge(base, 24, 25))] = 1.5f;
    }
    std::vector<double> xyz = m.positions;
    for (size_t i = 2; i < xyz.size(); i += 3) xyz[i] += 0.05 * std::sin(0.9 * double(i));
    LimitSurfaceOptions general;
    general.shortcuts = false;
    const LimitSurface a(load_scheme("loop"), base), b(load_scheme("loop"), base, general);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0, 0.5);
    for (Index f = 0; f < base.face_count(); ++f)
      for (int k = 0; k < 2; ++k) {
        const double u = unit(rng), v = k == 0 ? 0.0 : unit(rng);
        INFO("mesh of " << m.vertex_count << " vertices, face " << f << " at (" << u << ", " << v << ")");
        limit_test::check_same_bits(a, b, f, u, v, xyz, -1);
      }
  }
}
