#include "framework/limit/dual_crease_curve.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "framework/features/dual_features.h"

namespace subdiv {
namespace {

// Up to `count` crease vertices from `start` away from `from` (start first); `corner` is set
// when the walk reaches a corner of the mesh (a collapsing vertex) or the crease ends.
std::vector<Index> walk(const Level& L, Index start, Index from, int count, bool& corner) {
  std::vector<Index> out{start};
  Index prev = from, at = start;
  while (int(out.size()) < count) {
    if (dual_collapses(L, at)) {
      corner = true;
      return out;
    }
    Index next = kNone;
    for (Index e : L.ring_edges(at)) {
      if (!dual_sharp_edge(L, e)) continue;
      const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
      const Index y = a == at ? b : a;
      if (y != prev) next = y;
    }
    if (next == kNone || next == start) {
      corner = true;
      return out;
    }
    out.push_back(next);
    prev = at, at = next;
  }
  return out;
}

std::vector<Index> window(const Level& L, Index p, Index q, int m, bool& corner) {
  std::vector<Index> left = walk(L, p, q, m, corner);
  const std::vector<Index> right = walk(L, q, p, m, corner);
  std::reverse(left.begin(), left.end());
  left.insert(left.end(), right.begin(), right.end());
  return left;
}

}  // namespace

std::optional<std::vector<std::pair<Index, double>>> crease_middle_limit(const Level& parent, const Hierarchy& h,
                                                                         Index face, CreaseRun run, int corner_reach) {
  if (run.length != 2) return std::nullopt;
  const int n = parent.face_size(face);
  const Index p = parent.face(face)[size_t(run.first)], q = parent.face(face)[size_t((run.first + 1) % n)];
  const Level& child = h.levels[1];
  const ChildOrigins& o = h.origins[0];
  const StencilTable& rows = h.stencils[0];
  // The F-face's crease edge: its two crease corners, the one nearer p first.
  Index F = kNone;
  for (Index g = 0; g < child.face_count() && F == kNone; ++g)
    if (o.parent_face[size_t(g)] == face) F = g;
  if (F == kNone) return std::nullopt;
  const auto child_run = crease_run(child, F);
  if (!child_run || child_run->length != 2) return std::nullopt;
  const int cn = child.face_size(F);
  Index cp = child.face(F)[size_t(child_run->first)], cq = child.face(F)[size_t((child_run->first + 1) % cn)];
  auto weight = [&](Index v, Index on) {
    double w = 0;
    for (Index k = rows.offsets[size_t(v)]; k < rows.offsets[size_t(v) + 1]; ++k)
      if (rows.indices[size_t(k)] == on) w += rows.weights[size_t(k)];
    return w;
  };
  if (weight(cp, p) < weight(cq, p)) std::swap(cp, cq);
  for (int m = 2; m <= 8; ++m) {
    bool corner = false;
    const std::vector<Index> w0 = window(parent, p, q, m, corner);
    const std::vector<Index> w1 = window(child, cp, cq, m, corner);
    if (corner_reach > 0) (void)window(parent, p, q, m + corner_reach, corner);
    if (corner || w0.size() != w1.size()) return std::nullopt;
    const Eigen::Index k = Eigen::Index(w0.size());
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(k, k);
    double outside = 0;
    for (Eigen::Index i = 0; i < k; ++i) {
      const Index v = w1[size_t(i)];
      for (Index e = rows.offsets[size_t(v)]; e < rows.offsets[size_t(v) + 1]; ++e) {
        const auto it = std::find(w0.begin(), w0.end(), rows.indices[size_t(e)]);
        if (it == w0.end())
          outside += std::abs(rows.weights[size_t(e)]);
        else
          S(i, Eigen::Index(it - w0.begin())) += rows.weights[size_t(e)];
      }
    }
    if (outside > 1e-12) continue;
    // The left eigenvector of eigenvalue 1: S^T l = l.
    Eigen::EigenSolver<Eigen::MatrixXd> solver(S.transpose());
    Eigen::Index best = -1;
    for (Eigen::Index i = 0; i < k; ++i)
      if (best < 0 || std::abs(solver.eigenvalues()(i) - 1.0) < std::abs(solver.eigenvalues()(best) - 1.0)) best = i;
    if (best < 0 || std::abs(solver.eigenvalues()(best) - 1.0) > 1e-9) return std::nullopt;
    const Eigen::VectorXd l = solver.eigenvectors().col(best).real();
    const double sum = l.sum();
    if (std::abs(sum) < 1e-12) return std::nullopt;
    std::vector<std::pair<Index, double>> out;
    for (Eigen::Index i = 0; i < k; ++i) out.emplace_back(w0[size_t(i)], l(i) / sum);
    return out;
  }
  return std::nullopt;
}

int crease_end_reach(const Scheme& scheme) {
  int reach = 0;
  for (const StepRules& pass : scheme.steps)
    if (!pass.crease_ends.empty()) reach += pass.crease_ends.search_reach();
  return reach;
}

}  // namespace subdiv
