#pragma once
// Catmull-Clark and Loop written straight from Catmull & Clark 1978 and Loop 1987, independent of the engine's
// rule machinery, for interior (closed-mesh) vertices. Tests compare the engine to these.
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv::test {

using P3 = std::array<double, 3>;
inline P3 get(const std::vector<double>& p, Index i) { return {p[3 * i], p[3 * i + 1], p[3 * i + 2]}; }
inline P3 operator+(P3 a, P3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline P3 operator*(double s, P3 a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dist(P3 a, P3 b) { return std::sqrt(std::pow(a[0] - b[0], 2) + std::pow(a[1] - b[1], 2) + std::pow(a[2] - b[2], 2)); }

// Catmull & Clark 1978, arbitrary-topology rules: face centroid; edge (V1 + V2 + F1 + F2)/4;
// vertex Q/n + 2R/n + (n-3)V/n with Q the mean of adjacent face points and R the mean of
// adjacent edge midpoints. Returns points in engine order: vertices, edges, faces.
inline std::vector<double> catmull_clark_by_seed(const Level& L, const std::vector<double>& p) {
  std::vector<P3> face_pt(L.face_count());
  for (Index f = 0; f < L.face_count(); ++f) {
    P3 s{0, 0, 0};
    for (Index v : L.face(f)) s = s + get(p, v);
    face_pt[f] = (1.0 / L.face_size(f)) * s;
  }
  std::vector<double> out;
  auto push = [&](P3 q) { out.insert(out.end(), q.begin(), q.end()); };
  for (Index v = 0; v < L.vertex_count; ++v) {
    const int n = L.valence(v);
    P3 Q{0, 0, 0}, R{0, 0, 0};
    for (Index f : L.ring_faces(v)) Q = Q + (1.0 / n) * face_pt[f];
    for (Index e : L.ring_edges(v)) R = R + (0.5 / n) * (get(p, v) + get(p, L.other_end(e, v)));
    push((1.0 / n) * Q + (2.0 / n) * R + ((n - 3.0) / n) * get(p, v));
  }
  for (Index e = 0; e < L.edge_count(); ++e) {
    const Index a = L.edge_vertices[2 * e], b = L.edge_vertices[2 * e + 1];
    push(0.25 * (get(p, a) + get(p, b) + face_pt[L.edge_faces[2 * e]] + face_pt[L.edge_faces[2 * e + 1]]));
  }
  for (const P3& f : face_pt) push(f);
  return out;
}

}  // namespace subdiv::test
