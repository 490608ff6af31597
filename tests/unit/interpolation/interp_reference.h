#pragma once
// Independent computations for the interpolation tests, written from the papers' formulas
// with explicit geometry (no stencil tables, no library limit code):
// - Catmull-Clark's limit point on quads (Halstead, Kass & DeRose 1993);
// - Lin et al. 2015's two-step limit: the first step's face, edge and vertex points computed as
//   points, then Halstead et al.'s formula on them;
// - the paper's matrices M (15) and E (20) from G (16), for theorem 2.
#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "framework/io/mesh_read.h"
#include "framework/topology/level.h"
#include "support/test_meshes.h"

namespace subdiv::test {

using P3 = std::array<double, 3>;

inline P3 at(const std::vector<double>& x, Index v) { return {x[3 * v], x[3 * v + 1], x[3 * v + 2]}; }
inline P3 operator+(P3 a, const P3& b) {
  for (int c = 0; c < 3; ++c) a[c] += b[c];
  return a;
}
inline P3 operator*(double s, P3 a) {
  for (double& x : a) x *= s;
  return a;
}
inline double dist(const P3& a, const P3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Halstead et al.'s neighbourhood of an interior vertex among quads: edge neighbours e_j (CCW)
// and, in quad j, the vertex opposite v, f_j.
struct QuadRing {
  std::vector<Index> e, f;
};
inline QuadRing quad_ring(const Level& L, Index v) {
  QuadRing r;
  for (Index e : L.ring_edges(v)) r.e.push_back(L.other_end(e, v));
  const auto faces = L.ring_faces(v);
  for (size_t i = 0; i < faces.size(); ++i) {
    const auto face = L.face(faces[i]);
    int k = 0;
    while (face[k] != v) ++k;
    r.f.push_back(face[(k + 2) % 4]);
  }
  return r;
}

// Halstead, Kass & DeRose 1993: v_inf = (n^2 v + 4 sum e_j + sum f_j) / (n (n + 5)), interior quads.
inline P3 cc_limit_point(const Level& L, const std::vector<double>& x, Index v) {
  const QuadRing r = quad_ring(L, v);
  const double n = double(r.e.size());
  P3 s = (n * n) * at(x, v);
  for (Index e : r.e) s = s + 4.0 * at(x, e);
  for (Index f : r.f) s = s + at(x, f);
  return (1.0 / (n * (n + 5))) * s;
}

// Lin et al. 2015: first step by its rules as geometry, then Halstead et al.'s limit formula on the new
// points around v: v' = lambda v + (1 - lambda)(alpha E + (1 - alpha) F), edge points
// (v + e_j + fp_{j-1} + fp_j) / 4, face points the quads' centroids.
inline P3 two_step_limit_point(const Level& L, const std::vector<double>& x, Index v, double lambda) {
  const double alpha = 10.0 / 13.0;
  const QuadRing r = quad_ring(L, v);
  const size_t n = r.e.size();
  std::vector<P3> fp(n), ep(n);
  for (size_t j = 0; j < n; ++j)  // quad j is v, e_j, f_j, e_{j+1}
    fp[j] = 0.25 * (at(x, v) + at(x, r.e[j]) + at(x, r.f[j]) + at(x, r.e[(j + 1) % n]));
  for (size_t j = 0; j < n; ++j)  // ring edge j lies between quads j - 1 and j
    ep[j] = 0.25 * (at(x, v) + at(x, r.e[j]) + fp[(j + n - 1) % n] + fp[j]);
  P3 E{}, F{};
  for (size_t j = 0; j < n; ++j) E = E + (1.0 / n) * at(x, r.e[j]), F = F + (1.0 / n) * at(x, r.f[j]);
  const P3 vp = lambda * at(x, v) + (1 - lambda) * (alpha * E + (1 - alpha) * F);
  const double nn = double(n);
  P3 s = (nn * nn) * vp;
  for (size_t j = 0; j < n; ++j) s = s + 4.0 * ep[j] + fp[j];
  return (1.0 / (nn * (nn + 5))) * s;
}

// The paper's G(V, W) (16), without the "moving" condition: 1 for edge neighbours, 3/10
// for the vertex opposite in an incident quad, 0 otherwise.
inline double G(const Level& L, Index v, Index w) {
  const QuadRing r = quad_ring(L, v);
  for (Index e : r.e)
    if (e == w) return 1.0;
  for (Index f : r.f)
    if (f == w) return 0.3;
  return 0.0;
}

// Formula (6)'s coefficients for row vertex i: diagonal and off-diagonal scale.
inline double paper_beta(int n, double lambda) { return n * (1 - lambda) * 10.0 / 13.0 + 2.5; }

// M (15): rows and columns the moving vertices; E (20): rows the fixed, columns the moving
// vertices, e_qp = G(V_q, V_p) beta_{n_q} / (n_q (n_q + 5)) (the valence of the row vertex).
struct PaperMatrices {
  Eigen::MatrixXd M, E;
  std::vector<Index> P, Q;
};
inline PaperMatrices paper_matrices(const Level& L, const std::vector<double>& lambda,
                                    const std::vector<std::uint8_t>& moving) {
  PaperMatrices m;
  for (Index v = 0; v < L.vertex_count; ++v) (moving[v] ? m.P : m.Q).push_back(v);
  auto lam = [&](Index v) { return lambda.size() == 1 ? lambda[0] : lambda[v]; };
  auto entry = [&](Index row, Index col) {
    const int n = L.valence(row);
    const double d = double(n) * (n + 5);
    if (row == col) return (lam(row) * n * n + 7.0 * n / 4.0) / d;
    return G(L, row, col) * paper_beta(n, lam(row)) / d;
  };
  m.M.resize(Eigen::Index(m.P.size()), Eigen::Index(m.P.size()));
  m.E.resize(Eigen::Index(m.Q.size()), Eigen::Index(m.P.size()));
  for (size_t i = 0; i < m.P.size(); ++i)
    for (size_t j = 0; j < m.P.size(); ++j) m.M(Eigen::Index(i), Eigen::Index(j)) = entry(m.P[i], m.P[j]);
  for (size_t i = 0; i < m.Q.size(); ++i)
    for (size_t j = 0; j < m.P.size(); ++j) m.E(Eigen::Index(i), Eigen::Index(j)) = entry(m.Q[i], m.P[j]);
  return m;
}

// The paper's cross (figure 1): examples/meshes/cross.obj.
inline Mesh cross_mesh() {
  const MeshData d = read_mesh(std::string(SUBDIV_SOURCE_DIR) + "/examples/meshes/cross.obj");
  Mesh m;
  m.vertex_count = d.vertex_count();
  m.offsets.assign(d.face_offsets.begin(), d.face_offsets.end());
  m.corners.assign(d.face_vertices.begin(), d.face_vertices.end());
  m.positions = d.positions;
  return m;
}

}  // namespace subdiv::test
