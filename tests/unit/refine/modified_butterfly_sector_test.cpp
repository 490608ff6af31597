// Modified butterfly's interior edges next to a boundary or crease vertex v (docs/features.md,
// "Modified butterfly near boundaries and creases"; SubdivKit's own stencil, the interior
// rules being Zorin, Schröder & Sweldens 1996's). v's ring splits into sectors between its
// feature edges; in a sector of k faces with ring points p_0 .. p_k the new point of the edge
// (v, p_e) is
//     sum_i s_i p_i + (1 - sum_i s_i) v,   s_i = (c_i / k) cos((i - e) pi / k),
// c_i = 1/2 at i = 0, k and 1 between (trapezoid weights), and 1 - sum_i s_i =
// 1 - sin(e pi/k) cot(pi/(2k)) / k. An edge with one such end takes that end's stencil alone,
// one with two the average of both. Checked here against that closed form, written out, on
// meshes whose ring points are interior (one feature end) or on the boundary (two), on a
// boundary, on creases of sectors (3, 3), (2, 4), (1, 5) and (4, 4) and at corners; with linear
// precision on the half-disk p_i = (cos i pi/k, sin i pi/k) and on a regular grid with a
// straight boundary; and old vertices kept.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "unit/refine/modified_butterfly_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// The sector stencil's weight s_i for the edge to p_e in a sector of k faces.
double sector_weight(int k, int e, int i) {
  const double c = (i == 0 || i == k) ? 0.5 : 1.0;
  return c / k * std::cos((i - e) * std::numbers::pi / k);
}

// sum_i s_i p_i + (1 - sum_i s_i) v for the sector p_0 .. p_k around v (centre weight in
// its closed form, so that the sum is checked too).
Point sector_point(const Point& v, const std::vector<Point>& p, int e) {
  const int k = int(p.size()) - 1;
  const double pi = std::numbers::pi;
  const double centre = 1 - std::sin(e * pi / k) / (k * std::tan(pi / (2 * k)));
  Point q{centre * v[0], centre * v[1], centre * v[2]};
  for (int i = 0; i <= k; ++i)
    for (int c = 0; c < 3; ++c) q[c] += sector_weight(k, e, i) * p[size_t(i)][c];
  return q;
}

// A fan around vertex 0: ring points 1 .. m at angles a_i = span * i / (m - 1 or m), and, with
// `outer`, a second ring m + 1 .. 2m at twice the radius joined to the first by a band of
// triangles, so that the first ring's points are interior (except, on a boundary fan, the
// first and last). `closed`: the fan goes all the way round (m faces), else it spans pi
// (m - 1 faces, vertex 0 on the boundary). `exact`: the points lie exactly on circles
// (the half-disk configuration), z = 0; else they are perturbed and z is curved.
Mesh fan(int m, bool closed, bool outer, bool exact) {
  Mesh mesh;
  const double pi = std::numbers::pi;
  const int steps = closed ? m : m - 1;
  const double span = closed ? 2 * pi : pi;
  mesh.add_vertex(exact ? 0 : 0.03, exact ? 0 : -0.02, exact ? 0 : 0.1);
  for (int ring = 1; ring <= (outer ? 2 : 1); ++ring)
    for (int i = 0; i < m; ++i) {
      const double a = span * i / steps + (exact ? 0 : 0.09 * std::sin(3.0 * i + ring));
      const double r = ring * (exact ? 1 : 1 + 0.1 * std::cos(2.0 * i + ring));
      mesh.add_vertex(r * std::cos(a), r * std::sin(a), exact ? 0 : 0.3 * std::sin(a * 1.7 + ring) + 0.1 * ring * ring);
    }
  auto p = [&](int i) { return Index(1 + (i % m)); };
  auto q = [&](int i) { return Index(1 + m + (i % m)); };
  for (int i = 0; i < steps; ++i) {
    mesh.add_face({0, p(i), p(i + 1)});
    if (outer) mesh.add_face({p(i), q(i), q(i + 1)}), mesh.add_face({p(i), q(i + 1), p(i + 1)});
  }
  return mesh;
}

void check_close(const Point& got, const Point& want) {
  for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(want[c]).epsilon(1e-13));
}

// The sector p_first, p_first+1, ..., p_first+k of a fan's first ring (indices mod m).
std::vector<Point> sector_of(const Mesh& mesh, int m, int first, int k) {
  std::vector<Point> p;
  for (int i = 0; i <= k; ++i) p.push_back(at(mesh.positions, Index(1 + (first + i) % m)));
  return p;
}

}  // namespace

TEST_CASE("modified butterfly: an interior edge at a boundary vertex takes the sector stencil, k = 1..6") {
  for (int k = 1; k <= 6; ++k) {
    CAPTURE(k);
    const Mesh mesh = fan(k + 1, false, true, false);
    const Level base = mesh.level();
    const OneLevel r = refine_level(base, mesh.positions);
    const std::vector<Point> p = sector_of(mesh, k + 1, 0, k);
    const Point v = at(mesh.positions, 0);
    // Every interior edge at v has an interior other end: v's stencil alone.
    for (int e = 1; e < k; ++e) {
      CAPTURE(e);
      const Index edge = find_edge(base, 0, Index(1 + e));
      check_close(at(r.positions, edge_child(r.h.origins[0], edge)), sector_point(v, p, e));
    }
  }
}

TEST_CASE("modified butterfly: at a 300-valent boundary hub every interior edge takes the sector stencil, k = 300") {
  // A CAD-style fan from one boundary vertex: the weight tables hold this one large sector
  // (rules/weight_tables.h, LevelValences::sector_sizes), not every size up to 300.
  const int k = 300;
  const Mesh mesh = fan(k + 1, false, true, false);
  const Level base = mesh.level();
  const OneLevel r = refine_level(base, mesh.positions);
  const std::vector<Point> p = sector_of(mesh, k + 1, 0, k);
  const Point v = at(mesh.positions, 0);
  for (int e : {1, 2, 77, 150, 223, 298, 299}) {
    CAPTURE(e);
    const Index edge = find_edge(base, 0, Index(1 + e));
    const Point got = at(r.positions, edge_child(r.h.origins[0], edge)), want = sector_point(v, p, e);
    for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(want[c]).epsilon(1e-11));
  }
}

TEST_CASE("modified butterfly: an interior edge with both ends on the boundary averages both ends' stencils") {
  // A fan without the outer band: every ring point is a boundary vertex whose one sector has
  // two faces, in which the edge to v is p_1: its stencil is (p_0 + p_2) cos(pi/2)/4 + p_1/2 +
  // (1 - 1/2) v, the midpoint of the edge.
  for (int k = 2; k <= 6; ++k) {
    CAPTURE(k);
    const Mesh mesh = fan(k + 1, false, false, false);
    const Level base = mesh.level();
    const OneLevel r = refine_level(base, mesh.positions);
    const std::vector<Point> p = sector_of(mesh, k + 1, 0, k);
    const Point v = at(mesh.positions, 0);
    for (int e = 1; e < k; ++e) {
      CAPTURE(e);
      const Point at_v = sector_point(v, p, e);
      const Point at_p = sector_point(p[size_t(e)], {p[size_t(e - 1)], v, p[size_t(e + 1)]}, 1);
      Point want;
      for (int c = 0; c < 3; ++c) {
        want[c] = 0.5 * (at_v[c] + at_p[c]);
        CHECK(at_p[c] == doctest::Approx(0.5 * (v[c] + p[size_t(e)][c])));
      }
      const Index edge = find_edge(base, 0, Index(1 + e));
      check_close(at(r.positions, edge_child(r.h.origins[0], edge)), want);
    }
  }
}

TEST_CASE("modified butterfly: at a crease or corner vertex each sector between feature edges has its stencil") {
  // Crease sectors (3, 3), (2, 4), (1, 5), (4, 4); corners of three feature edges with
  // sectors (2, 2, 2) and (1, 2, 3).
  struct Case {
    int m;                  // ring size
    std::vector<int> sharp;  // ring positions of the feature edges, ascending
  };
  for (const Case& s : {Case{6, {0, 3}}, Case{6, {0, 2}}, Case{6, {0, 1}}, Case{8, {0, 4}}, Case{6, {0, 2, 4}},
                        Case{6, {0, 1, 3}}}) {
    CAPTURE(s.m);
    CAPTURE(s.sharp.size());
    CAPTURE(s.sharp[1]);
    const Mesh mesh = fan(s.m, true, true, false);
    Level base = mesh.level();
    // Each feature line runs p_i - v and on to q_i on the outer boundary.
    base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
    for (int i : s.sharp) {
      base.edge_sharpness[size_t(find_edge(base, 0, Index(1 + i)))] = 10.f;
      base.edge_sharpness[size_t(find_edge(base, Index(1 + i), Index(1 + s.m + i)))] = 10.f;
    }
    const OneLevel r = refine_level(base, mesh.positions);
    const Point v = at(mesh.positions, 0);
    for (size_t t = 0; t < s.sharp.size(); ++t) {
      const int first = s.sharp[t], last = t + 1 < s.sharp.size() ? s.sharp[t + 1] : s.m;
      for (int i = first + 1; i < last; ++i) {
        CAPTURE(i);
        const Point want = sector_point(v, sector_of(mesh, s.m, first, last - first), i - first);
        const Index edge = find_edge(base, 0, Index(1 + i));
        check_close(at(r.positions, edge_child(r.h.origins[0], edge)), want);
      }
    }
  }
}

TEST_CASE("modified butterfly: next to a semi-sharp crease of sharpness s < 1 the sector stencil is blended by s") {
  // DeRose, Kass & Truong 1998's fractional sharpness, as the vertex rules blend: a crease of
  // sharpness s <= 1 is smooth one level down, so an interior edge at its vertices takes s of
  // the sector stencil and 1 - s of the smooth stencil. The new point is linear in s, equal to
  // the smooth scheme's at s = 0 and to the sharp crease's at s = 1.
  const int m = 6;
  const Mesh mesh = fan(m, true, true, false);
  auto refined = [&](float s) {
    Level base = mesh.level();
    base.edge_sharpness.assign(size_t(base.edge_count()), 0.f);
    for (int i : {0, 3}) {
      base.edge_sharpness[size_t(find_edge(base, 0, Index(1 + i)))] = s;
      base.edge_sharpness[size_t(find_edge(base, Index(1 + i), Index(1 + m + i)))] = s;
    }
    return std::pair{base, refine_level(base, mesh.positions)};
  };
  const auto [base, smooth] = refined(0.f);
  const OneLevel sharp = refined(1.f).second;
  // Edges at the crease vertex v (index 0) and at the crease vertex p_0 (index 1).
  std::vector<Index> edges;
  for (int i : {1, 2, 4, 5}) edges.push_back(find_edge(base, 0, Index(1 + i)));
  edges.push_back(find_edge(base, 1, 2));
  edges.push_back(find_edge(base, 1, Index(1 + m + 1)));
  double moved = 0;
  for (Index e : edges) {
    const Point p0 = at(smooth.positions, edge_child(smooth.h.origins[0], e));
    const Point p1 = at(sharp.positions, edge_child(sharp.h.origins[0], e));
    for (int c = 0; c < 3; ++c) moved = std::max(moved, std::abs(p1[c] - p0[c]));
    for (float s : {0.25f, 0.5f, 0.9f}) {
      CAPTURE(s);
      const OneLevel r = refined(s).second;
      const Point got = at(r.positions, edge_child(r.h.origins[0], e));
      for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(s * p1[c] + (1 - s) * p0[c]).epsilon(1e-13));
    }
  }
  CHECK(moved > 1e-3);  // the sector stencil differs from the smooth one here
}

TEST_CASE("modified butterfly: on the half-disk the sector stencil reproduces linear data (new point = midpoint)") {
  // p_i = (cos i pi/k, sin i pi/k), v = 0: the weights are DCT-I (cosine) and DST-I (sine)
  // coefficients, so x and y are halved exactly; the rule being affine, every linear function
  // is reproduced, and the new point of (v, p_e) is the midpoint p_e / 2.
  for (int k = 2; k <= 8; ++k) {
    CAPTURE(k);
    Mesh mesh = fan(k + 1, false, true, true);
    for (size_t i = 0; i < mesh.positions.size(); i += 3)
      mesh.positions[i + 2] = 0.7 * mesh.positions[i] - 0.4 * mesh.positions[i + 1] + 2;  // a plane
    const Level base = mesh.level();
    const OneLevel r = refine_level(base, mesh.positions);
    for (int e = 1; e < k; ++e) {
      CAPTURE(e);
      const Point got = at(r.positions, edge_child(r.h.origins[0], find_edge(base, 0, Index(1 + e))));
      const Point v = at(mesh.positions, 0), pe = at(mesh.positions, Index(1 + e));
      for (int c = 0; c < 3; ++c) CHECK(got[c] == doctest::Approx(0.5 * (v[c] + pe[c])).epsilon(1e-13));
    }
  }
}

TEST_CASE("modified butterfly: a regular grid with a straight boundary refines linear data to midpoints, levels 1-3") {
  // An equilateral triangle grid (interior valence 6, boundary valence 4: sectors of 3 faces,
  // the half-disk at k = 3; corners of one and two faces, where k = 2 gives the midpoint), sheared: the rules are affine, so linear precision survives.
  const int nx = 7, ny = 5;
  Mesh mesh;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double x = i + 0.5 * j, y = j * std::sqrt(3.0) / 2;
      mesh.add_vertex(x + 0.3 * y, y, 0.25 * x - 0.6 * y + 1);
    }
  auto id = [&](int i, int j) { return Index(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.add_face({id(i, j), id(i + 1, j), id(i, j + 1)});
      mesh.add_face({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  // The grid's corners are tagged, so that the boundary's 4-point rule runs along each straight
  // side (extrapolating past the corner) rather than round the corner.
  Level base = mesh.level();
  base.vertex_sharpness.assign(size_t(base.vertex_count), 0.f);
  for (Index corner : {id(0, 0), id(nx, 0), id(0, ny), id(nx, ny)}) base.vertex_sharpness[size_t(corner)] = 10.f;
  for (int levels = 1; levels <= 3; ++levels) {
    CAPTURE(levels);
    RefineOptions options;
    options.levels = levels;
    Refined r{refine(*load_scheme("modified-butterfly"), base, options), {}};
    r.positions = interpolate(r.hierarchy, levels, mesh.positions, 3);
    const Level& parent = r.hierarchy.levels[size_t(levels - 1)];
    const std::vector<double> before = interpolate(r.hierarchy, levels - 1, mesh.positions, 3);
    const ChildOrigins& o = r.hierarchy.origins[size_t(levels - 1)];
    double worst = 0;
    for (Index c = 0; c < Index(o.kind.size()); ++c) {
      if (o.kind[c] != OriginKind::Edge) continue;
      const Index e = o.parent[c];
      const Point a = at(before, parent.edge_vertices[2 * e]), b = at(before, parent.edge_vertices[2 * e + 1]);
      const Point got = at(r.positions, c);
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(got[k] - 0.5 * (a[k] + b[k])));
    }
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("modified butterfly: old vertices stay at boundary and crease vertices of every sector size") {
  for (int k = 1; k <= 6; ++k) {
    const Mesh mesh = fan(k + 1, false, true, false);
    const OneLevel r = refine_level(mesh.level(), mesh.positions);
    const ChildOrigins& o = r.h.origins[0];
    for (Index c = 0; c < Index(o.kind.size()); ++c)
      if (o.kind[c] == OriginKind::Vertex) CHECK(at(r.positions, c) == at(mesh.positions, o.parent[c]));
  }
}
