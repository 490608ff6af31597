// Catmull-Clark's limit at (face, u, v) around an interior vertex of valence 2: a quad of a
// closed mesh split in two by a new vertex x joined to two opposite corners, so that x has
// two edges and two faces. Its local subdivision matrix on the 1-ring (x, e_0, f_0, e_1, f_1)
// has the eigenvalues 1, 1/4, 1/4, -1/4, 1/8 (docs/analysis.md); the references here are
// mathematics and OpenSubdiv: Bfr away from the vertex (exact there with its approximation
// level at 10), the left eigenvector of 1 at the vertex, OpenSubdiv's uniform refinement
// converging to it, continuity across shared edges, finite differences, and the rate 1/4.
#include <doctest/doctest.h>

#include "unit/limit/bfr_surface.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

#include <algorithm>
#include <cmath>
#include <random>

#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "unit/limit/limit_meshes.h"

using namespace subdiv;
using subdiv::limit_test::bumped;
using subdiv::limit_test::central_difference_error;

using subdiv_test::osd_mesh;

namespace {

// The mesh with face `split` = (a, b, c, d) replaced by (x, a, b, c) and (x, c, d, a): the
// new vertex x (last) has valence 2 and is corner 0 of the two new faces (the last two).
test::Mesh with_valence_two(const test::Mesh& m, Index split, double lift) {
  test::Mesh out;
  out.positions = m.positions;
  out.vertex_count = m.vertex_count;
  const Index faces = Index(m.offsets.size()) - 1;
  std::array<Index, 4> q{};
  for (Index f = 0; f < faces; ++f) {
    const Index first = m.offsets[size_t(f)], size = m.offsets[size_t(f) + 1] - first;
    if (f == split) {
      REQUIRE(size == 4);
      for (size_t k = 0; k < 4; ++k) q[k] = m.corners[size_t(first) + k];
      continue;
    }
    out.corners.insert(out.corners.end(), m.corners.begin() + first, m.corners.begin() + first + size);
    out.offsets.push_back(Index(out.corners.size()));
  }
  std::array<double, 3> centre{};
  for (Index v : q)
    for (size_t i = 0; i < 3; ++i) centre[i] += 0.25 * m.positions[size_t(3 * v) + i];
  out.add_vertex(centre[0], centre[1], centre[2] + lift);
  const Index x = out.vertex_count - 1;
  out.add_face({x, q[0], q[1], q[2]});
  out.add_face({x, q[2], q[3], q[0]});
  return out;
}

struct Case {
  const char* name;
  test::Mesh mesh;
};

// A torus (x's neighbours a and c then have valence 5, the rest 4) and a cube (x next to
// valence-3 corners), both closed and bumped so that no symmetry hides a wrong weight.
std::vector<Case> cases() {
  return {{"torus", bumped(with_valence_two(test::torus(6, 6), 14, 0.3))},
          {"cube", bumped(with_valence_two(test::cube(), 0, -0.2))}};
}

double distance(const std::vector<double>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

std::array<double, 3> point(const test::Mesh& m, Index v) {
  return {m.positions[size_t(3 * v)], m.positions[size_t(3 * v + 1)], m.positions[size_t(3 * v + 2)]};
}

}  // namespace

TEST_CASE("Valence 2 inside: Bfr's limit and derivatives everywhere but within its approximated corners") {
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.name));
    const LimitSurface surface(load_scheme("catmull-clark"), c.mesh.level());
    const subdiv_test::BfrLimit bfr(osd_mesh(c.mesh), {subdiv_test::OsdScheme::CatmullClark}, 10, 10);
    const Index faces = surface.base().face_count();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double position = 0, derivative = 0;
    int near_x = 0;
    for (int i = 0; i < 400; ++i) {
      // Half of the points in x's two faces, a quarter of those close to x (down to 1e-3).
      const Index f = i % 2 ? faces - 1 - Index(i / 2 % 2) : Index(rng() % unsigned(faces));
      double u = unit(rng), v = unit(rng);
      if (i % 8 == 1) u = std::pow(10.0, -3 * unit(rng)), v = std::pow(10.0, -3 * unit(rng));
      // Bfr approximates within 2^-10 of an irregular corner; these stay outside 2^-9.
      bool near_corner = false;
      for (double cu : {0.0, 1.0})
        for (double cv : {0.0, 1.0}) near_corner |= std::max(std::fabs(u - cu), std::fabs(v - cv)) < 1.0 / 512;
      if (near_corner) continue;
      near_x += f >= faces - 2 && std::max(u, v) < 0.01;
      const LimitSample ours = surface.evaluate(f, u, v, c.mesh.positions, 3);
      const auto ref = bfr.evaluate(int(f), u, v);
      REQUIRE(ours.has_derivatives);
      position = std::max(position, distance(ours.position, ref.p));
      derivative = std::max({derivative, distance(ours.du, ref.du), distance(ours.dv, ref.dv)});
    }
    CHECK(near_x >= 5);
    CHECK(position < 1e-12);
    CHECK(derivative < 1e-10);
    MESSAGE(std::string(c.name) << ": within " << position << " of Bfr, derivatives within " << derivative);
  }
}

TEST_CASE("Valence 2 inside: the vertex is its limit mask, the left eigenvector (4, 4, 1, 4, 1)/14 of its ring") {
  // The 1-ring matrix of Catmull-Clark at valence 2 (Stam 1998's S for n = 2) has the left
  // eigenvector of 1 proportional to (4, 4, 1, 4, 1) over (x, e_0, f_0, e_1, f_1): the
  // formula (n^2 x + 4 sum e_j + sum f_j) / (n (n + 5)) of Halstead, Kass & DeRose 1993 at
  // n = 2. OpenSubdiv's Sdc gives a valence-2 vertex the corner mask (x itself) instead, so
  // its limit stencils are no reference; its uniform refinement is: x's descendants must
  // converge to the mask's point, their distance shrinking by 1/16 every two levels
  // (eigenvalues 1/4 and -1/4 of modulus 1/4, then 1/8).
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.name));
    const LimitSurface surface(load_scheme("catmull-clark"), c.mesh.level());
    const Index faces = surface.base().face_count();
    const Index x = c.mesh.vertex_count - 1;
    const auto ring = surface.base().face(faces - 2);  // x, a, b, c
    const auto other = surface.base().face(faces - 1);  // x, c, d, a
    const std::array<Index, 5> labels{x, ring[1], ring[2], ring[3], other[2]};
    const std::array<double, 5> mask{4.0 / 14, 4.0 / 14, 1.0 / 14, 4.0 / 14, 1.0 / 14};
    std::array<double, 3> expected{};
    for (size_t k = 0; k < 5; ++k)
      for (size_t i = 0; i < 3; ++i) expected[i] += mask[k] * point(c.mesh, labels[k])[i];
    for (Index f : {faces - 2, faces - 1}) {
      const LimitSample at = surface.evaluate(f, 0, 0, c.mesh.positions, 3);
      CHECK(distance(at.position, expected) < 1e-14);
      CHECK_FALSE(at.has_derivatives);  // the vertex is extraordinary: no tangent plane (docs/limit.md)
      const LimitStencil s = surface.stencil(f, 0, 0, 0);
      double worst = 0;
      for (size_t e = 0; e < s.vertices.size(); ++e) {
        const auto k = std::find(labels.begin(), labels.end(), s.vertices[e]) - labels.begin();
        worst = std::max(worst, std::fabs(s.position[e] - (k < 5 ? mask[size_t(k)] : 0.0)));
      }
      CHECK(worst < 1e-15);
    }
    // Level 8 (the torus then has 2.4M faces): enough to see the rate.
    const auto osd = subdiv_test::osd_refine(osd_mesh(c.mesh), {subdiv_test::OsdScheme::CatmullClark}, 8);
    std::vector<double> gap;
    for (int l = 0; l <= 8; ++l) {
      const auto p = osd.levels[size_t(l)].position(int(x));  // vertex children keep their index
      gap.push_back(std::hypot(p[0] - expected[0], p[1] - expected[1], p[2] - expected[2]));
    }
    // 16 times the ratio minus 1 is the 1/8 part's share, halving every level (measured:
    // 0.015, 0.0063, 0.0031, 0.0016, 0.0008 on the torus from level 2); a wrong limit point
    // would leave a gap that stops shrinking.
    for (int l = 2; l + 2 <= 8; ++l) {
      CAPTURE(l);
      CHECK(std::fabs(16 * gap[size_t(l + 2)] / gap[size_t(l)] - 1) < 0.2 * std::ldexp(1.0, -l));
    }
  }
}

TEST_CASE("Valence 2 inside: continuous across the faces' shared edges, with the edges' derivative") {
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.name));
    const LimitSurface surface(load_scheme("catmull-clark"), c.mesh.level());
    const Level& L = surface.base();
    const Index faces = L.face_count();
    double position = 0, tangent = 0;
    int edges = 0;
    for (Index f : {faces - 2, faces - 1}) {
      const auto fe = L.face_edge_list(f);
      for (int k = 0; k < 4; ++k) {
        const Index e = fe[size_t(k)];
        const Index g = L.edge_faces[size_t(2 * e)] == f ? L.edge_faces[size_t(2 * e + 1)] : L.edge_faces[size_t(2 * e)];
        const auto ge = L.face_edge_list(g);
        const int j = int(std::find(ge.begin(), ge.end(), e) - ge.begin());
        ++edges;
        // Down to 1e-9 from x (edges 0 and 3 end there); 1e-3 from the other corners, where
        // extraordinary vertices of valence 3 and 5 make the derivatives grow like
        // (2 lambda)^levels and lose relative precision as they do (docs/limit.md).
        std::vector<double> ts{1e-3, 0.1, 0.37, 0.5, 0.81, 1 - 1e-3};
        if (k == 0) ts.push_back(1e-9);
        if (k == 3) ts.push_back(1 - 1e-9);
        for (double t : ts) {
          // The neighbour runs along the edge the other way.
          const auto a = limit_test::quad_edge_point(k, t), b = limit_test::quad_edge_point(j, 1 - t);
          const LimitSample p = surface.evaluate(f, a[0], a[1], c.mesh.positions, 3);
          const LimitSample q = surface.evaluate(g, b[0], b[1], c.mesh.positions, 3);
          position = std::max(position, limit_test::distance(p.position, q.position));
          // The derivative along the edge: +d/du, +d/dv, -d/du, -d/dv for edges 0..3.
          auto along = [](const LimitSample& s, int edge, size_t i) {
            const double sign = edge < 2 ? 1.0 : -1.0;
            return sign * (edge % 2 == 0 ? s.du[i] : s.dv[i]);
          };
          for (size_t i = 0; i < 3; ++i)
            tangent = std::max(tangent, std::fabs(along(p, k, i) + along(q, j, i)) / std::max(1.0, std::fabs(along(p, k, i))));
        }
      }
    }
    CHECK(edges == 8);
    CHECK(position < 1e-13);
    CHECK(tangent < 1e-11);  // relative to the derivative where it exceeds 1
  }
}

TEST_CASE("Valence 2 inside: derivatives are the evaluated points' central differences") {
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.name));
    const LimitSurface surface(load_scheme("catmull-clark"), c.mesh.level());
    const Index faces = surface.base().face_count();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    double worst = 0;
    for (int i = 0; i < 20; ++i)
      worst = std::max(worst, central_difference_error(surface, faces - 1 - i % 2, unit(rng), unit(rng), c.mesh.positions));
    CHECK(worst < 1e-7);
    // Near x the surface bends faster: a smaller step.
    for (Index f : {faces - 2, faces - 1})
      CHECK(central_difference_error(surface, f, 0.013, 0.021, c.mesh.positions, 1e-6) < 1e-6);
  }
}

TEST_CASE("Valence 2 inside: towards the vertex the limit converges at the subdominant rate 1/4") {
  // Along a ray (t u0, t v0) the limit minus the vertex's is sum_i lambda_i^m phi_i over the
  // eigenvalues of the vertex's step: with 1/4, 1/4, -1/4 leading, halving t 2 times scales
  // it by exactly 1/16 up to the next eigenvalue's share (1/8: relative 2^-m), and the
  // parametric derivatives (one factor 2 per level) by 1/4. Points down to 2^-40 are reached
  // through powers of the step (limit_nodes.h).
  for (const Case& c : cases()) {
    CAPTURE(std::string(c.name));
    const LimitSurface surface(load_scheme("catmull-clark"), c.mesh.level());
    const Index f = surface.base().face_count() - 1;
    const LimitSample centre = surface.evaluate(f, 0, 0, c.mesh.positions, 3);
    std::vector<double> gap, slope;
    for (int m = 0; m <= 40; ++m) {
      const double t = std::ldexp(1.0, -m);
      const LimitSample s = surface.evaluate(f, 0.6 * t, 0.3 * t, c.mesh.positions, 3);
      gap.push_back(limit_test::distance(s.position, centre.position));
      slope.push_back(std::hypot(s.du[0], s.du[1], s.du[2]));
    }
    // The offsets from 12 levels on (the 1/8 part below 1e-3 of them) while they stay far
    // above the positions' round-off (4^-20 ~ 1e-12 against 1e-16); the derivatives, rows
    // carried down without cancellation, all the way.
    for (int m = 12; m + 2 <= 40; ++m) {
      CAPTURE(m);
      if (m + 2 <= 20) CHECK(gap[size_t(m + 2)] / gap[size_t(m)] == doctest::Approx(1.0 / 16).epsilon(1e-3));
      CHECK(slope[size_t(m + 2)] / slope[size_t(m)] == doctest::Approx(1.0 / 4).epsilon(1e-3));
    }
  }
}

#endif
