// Circle-preserving four-point subdivision (M. Sabin, N. Dodgson, "A circle-preserving variant
// of the four-point subdivision scheme", Mathematical Methods for Curves and Surfaces:
// Tromsø 2004). A non-linear plugin: no stencils, the engine applies it.
//
// The linear four-point scheme puts the new point P between B and C (neighbours A, D) where
// the second difference at P is the mean of those at B and C (Sabin & Dodgson 2004):
//     [B + C - 2P] / (1/4) = ([A + C - 2B] + [B + D - 2C]) / 2.
// Here each end's second difference is replaced by its circle: the circle through A, B, C
// puts P at the midpoint of its arc BC (the arc away from A), the circle through B, C, D at
// the midpoint of its arc BC (away from D), and P is the mean of the two. When all four
// points lie on one circle both arcs are the same arc, so P lies on that circle (exactly,
// for any spacing); collinear points give the chord midpoint, as the linear scheme does
// on evenly spaced lines. An end of an open polyline uses the one circle it has.
//
// Registered:
//  - curve scheme "circle-four-point" (non-linear): polylines and closed polygons;
//  - surface scheme "circle-quad" (non-linear, quad meshes): the same rule along the mesh
//    lines of a quad mesh (Kobbelt's interpolatory quad scheme with circles for second
//    differences). Old vertices stay; an edge point uses the lines through the edge's
//    ends; a face point is the mean of the rule applied across the face in both
//    directions to the new edge points. A torus sampled on a regular grid of its angles
//    stays on the torus at every level.
#include <array>
#include <cmath>
#include <vector>

#include "framework/plugin/mesh_lines.h"
#include "framework/plugin/plugin_api.h"
#include "framework/util/error.h"

namespace {

using subdiv::Index;
using subdiv::kNone;
using Vec = std::array<double, 3>;

Vec operator+(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec operator-(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec operator*(double s, const Vec& a) { return {s * a[0], s * a[1], s * a[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The midpoint of the arc BC of the circle through A, B, C that does not contain A; the
// chord midpoint when A, B, C are (nearly) collinear, where the circle becomes a line.
Vec arc_midpoint(const Vec& A, const Vec& B, const Vec& C) {
  const Vec u = C - B, M = 0.5 * (B + C);
  const double d2 = dot(u, u);
  if (d2 == 0.0) return M;
  const Vec a = A - M;
  const double along = dot(a, u) / std::sqrt(d2);  // A in the plane of the circle: (along, across)
  const Vec w = a - (dot(a, u) / d2) * u;
  const double across = std::sqrt(dot(w, w));
  if (across <= 1e-14 * (std::sqrt(dot(a, a)) + std::sqrt(d2))) return M;
  const double half = 0.5 * std::sqrt(d2);
  // Centre at distance y0 from M towards A; radius R. The arc away from A reaches
  // h = R - y0 beyond the chord (written without cancellation when y0 > 0).
  const double y0 = (along * along + across * across - half * half) / (2.0 * across);
  const double R = std::hypot(y0, half);
  const double h = y0 > 0 ? half * half / (R + y0) : R - y0;
  return M - (h / across) * w;
}

// The new point between B and C with neighbours A and D (either may be missing).
Vec new_point(const Vec* A, const Vec& B, const Vec& C, const Vec* D) {
  if (A && D) return 0.5 * (arc_midpoint(*A, B, C) + arc_midpoint(*D, B, C));
  if (A) return arc_midpoint(*A, B, C);
  if (D) return arc_midpoint(*D, B, C);
  return 0.5 * (B + C);
}

Vec point(std::span<const double> values, Index i, int dim) {
  Vec p{0, 0, 0};
  for (int d = 0; d < dim; ++d) p[d] = values[size_t(i) * dim + d];
  return p;
}

void check_dim(int dim, const char* scheme) {
  if (dim < 2 || dim > 3)
    throw subdiv::Error(std::string(scheme) + " refines 2D or 3D points, not " + std::to_string(dim) + " numbers per point");
}

// One step of the curve scheme: old points stay, one new point per segment.
std::vector<double> circle_four_point_step(std::span<const double> points, int dim, bool closed, int) {
  check_dim(dim, "circle-four-point");
  const long n = long(points.size()) / dim;
  if (n < 2) return {points.begin(), points.end()};
  const long segments = closed ? n : n - 1;
  std::vector<double> out;
  out.reserve(size_t(n + segments) * dim);
  auto at = [&](long i) { return point(points, Index(closed ? ((i % n) + n) % n : i), dim); };
  auto exists = [&](long i) { return closed || (i >= 0 && i < n); };
  for (long i = 0; i < n; ++i) {
    for (int d = 0; d < dim; ++d) out.push_back(points[size_t(i) * dim + d]);
    if (i >= segments) break;
    const Vec B = at(i), C = at(i + 1);
    Vec A{}, D{};
    const bool has_a = exists(i - 1) && (closed ? n >= 3 : true), has_d = exists(i + 2) && (closed ? n >= 3 : true);
    if (has_a) A = at(i - 1);
    if (has_d) D = at(i + 2);
    const Vec P = new_point(has_a ? &A : nullptr, B, C, has_d ? &D : nullptr);
    for (int d = 0; d < dim; ++d) out.push_back(P[d]);
  }
  return out;
}

// The circle-quad step on the values of a quad mesh refined by the quad split.
void circle_quad_step(const subdiv::NonlinearStepInput& in, std::span<const double> parent, std::span<double> child,
                      int channels) {
  check_dim(channels, "circle-quad");
  const subdiv::Level& L = in.parent;
  // Child index of each parent vertex, edge and face (quad split: one each).
  std::vector<Index> of_vertex(L.vertex_count, kNone), of_edge(L.edge_count(), kNone), of_face(L.face_count(), kNone);
  for (Index c = 0; c < Index(in.origins.kind.size()); ++c) {
    const Index p = in.origins.parent[c];
    switch (in.origins.kind[c]) {
      case subdiv::OriginKind::Vertex: of_vertex[p] = c; break;
      case subdiv::OriginKind::Edge: of_edge[p] = c; break;
      case subdiv::OriginKind::Face: of_face[p] = c; break;
      default: throw subdiv::Error("circle-quad expects the quad split");
    }
  }
  auto set = [&](Index c, const Vec& p) {
    for (int d = 0; d < channels; ++d) child[size_t(c) * channels + d] = p[d];
  };
  for (Index v = 0; v < L.vertex_count; ++v) set(of_vertex[v], point(parent, v, channels));  // interpolatory
  // Edge points: the rule along the line of the edge.
  std::vector<Vec> edge_points(L.edge_count());
  for (Index e = 0; e < L.edge_count(); ++e) {
    const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
    const Index before = subdiv::vertex_beyond(L, in.features, e, a), after = subdiv::vertex_beyond(L, in.features, e, b);
    const Vec A = before != kNone ? point(parent, before, channels) : Vec{};
    const Vec D = after != kNone ? point(parent, after, channels) : Vec{};
    edge_points[e] = new_point(before != kNone ? &A : nullptr, point(parent, a, channels), point(parent, b, channels),
                               after != kNone ? &D : nullptr);
    set(of_edge[e], edge_points[e]);
  }
  // Face points: the rule across the face through the new points of opposite edges, in both
  // directions, averaged.
  for (Index f = 0; f < L.face_count(); ++f) {
    const auto edges = L.face_edge_list(f);
    Vec sum{0, 0, 0};
    for (int dir = 0; dir < 2; ++dir) {
      const Index e0 = edges[dir], e2 = edges[dir + 2];
      const Index before = subdiv::parallel_edge_across(L, in.features, f, e0);
      const Index after = subdiv::parallel_edge_across(L, in.features, f, e2);
      sum = sum + new_point(before != kNone ? &edge_points[before] : nullptr, edge_points[e0], edge_points[e2],
                            after != kNone ? &edge_points[after] : nullptr);
    }
    set(of_face[f], 0.5 * sum);
  }
}

void register_circle_preserving(subdiv::PluginRegistry& registry) {
  subdiv::CurveSchemeSpec curve;
  curve.name = "circle-four-point";
  curve.description =
      "Sabin-Dodgson circle-preserving 4-point scheme (non-linear): points on a circle stay on it; lines stay lines";
  curve.nonlinear = [](const subdiv::ParameterValues&) -> subdiv::PolylineRule { return circle_four_point_step; };
  registry.add_curve_scheme(std::move(curve));

  subdiv::SurfaceSchemeSpec quad;
  quad.name = "circle-quad";
  quad.description = "interpolatory quad scheme with the circle-preserving 4-point rule along mesh lines "
                     "(non-linear; quads only): a regularly sampled torus stays on the torus";
  quad.split = "quad";
  quad.required_face_size = 4;
  quad.nonlinear = [](const subdiv::ParameterValues&) -> subdiv::NonlinearRule { return circle_quad_step; };
  registry.add_surface_scheme(std::move(quad));
}

}  // namespace

SUBDIV_PLUGIN("circle-preserving", "1.0.0", register_circle_preserving)
