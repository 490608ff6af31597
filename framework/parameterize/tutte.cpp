#include "framework/parameterize/tutte.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <array>
#include <cmath>
#include <fmt/format.h>

#include "framework/parameterize/boundary_layout.h"
#include "framework/parameterize/disc_check.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 edge_vector(std::span<const double> p, Index from, Index to) {
  return {p[size_t(3 * to)] - p[size_t(3 * from)], p[size_t(3 * to + 1)] - p[size_t(3 * from + 1)],
          p[size_t(3 * to + 2)] - p[size_t(3 * from + 2)]};
}
double length(const Vec3& a) { return std::hypot(a[0], a[1], a[2]); }

// tan(a/2) of the angle a between two vectors, from |u||v| - u.v over |u x v| (no acos).
double tan_half_angle(const Vec3& u, const Vec3& v) {
  const Vec3 c{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const double s = length(c);
  return s > 0 ? (length(u) * length(v) - dot) / s : 0.0;
}

void add(std::vector<std::pair<Index, double>>& row, Index j, double w) {
  for (auto& entry : row)
    if (entry.first == j) {
      entry.second += w;
      return;
    }
  row.emplace_back(j, w);
}

// Mean-value weights (Floater 2003, eq. 3.1): every face corner at v adds tan(a/2) to the
// two edges it lies between; each sum is divided by the edge's length.
std::vector<std::pair<Index, double>> mean_value_row(const Level& level, std::span<const double> p, Index v) {
  std::vector<std::pair<Index, double>> row;
  for (Index j : level.ring_edges(v)) add(row, level.other_end(j, v), 0.0);
  const auto faces = level.ring_faces(v);
  for (size_t i = 0; i < faces.size(); ++i) {
    const auto corners = level.face(faces[i]);
    const size_t k = corners.size();
    const size_t at = level.vertex_face_corner[size_t(level.vertex_face_offsets[size_t(v)]) + i];
    const Index next = corners[(at + 1) % k], prev = corners[(at + k - 1) % k];
    const double t = tan_half_angle(edge_vector(p, v, next), edge_vector(p, v, prev));
    add(row, next, t);
    add(row, prev, t);
  }
  for (auto& entry : row) {
    const double d = length(edge_vector(p, v, entry.first));
    entry.second = d > 0 ? entry.second / d : 0.0;
  }
  return row;
}

void normalise(std::vector<std::pair<Index, double>>& row, Index v) {
  double sum = 0;
  for (const auto& entry : row) sum += entry.second;
  if (!(sum > 0) || !std::isfinite(sum))
    throw Error(fmt::format("vertex {} (counted from 0): its mean-value weights do not add up to a positive number "
                            "(its neighbours coincide with it or with each other); use uniform weights",
                            v));
  for (auto& entry : row) entry.second /= sum;
}

// The interior rows as one sparse system A x = b with the boundary's uv on the right.
struct System {
  Eigen::SparseMatrix<double> A;
  Eigen::MatrixXd b;
};

System build_system(const Level& level, std::span<const double> p, const std::vector<Index>& unknown,
                    const std::vector<Index>& interior, const std::vector<double>& uv, TutteWeights weights) {
  std::vector<Eigen::Triplet<double>> entries;
  System s{Eigen::SparseMatrix<double>(Eigen::Index(interior.size()), Eigen::Index(interior.size())),
           Eigen::MatrixXd::Zero(Eigen::Index(interior.size()), 2)};
  for (size_t r = 0; r < interior.size(); ++r) {
    const Index v = interior[r];
    // Uniform rows are scaled by the valence: the graph Laplacian, symmetric positive definite.
    const auto row = tutte_row(level, p, v, weights);
    const double scale = weights == TutteWeights::Uniform ? double(row.size()) : 1.0;
    entries.emplace_back(Eigen::Index(r), Eigen::Index(r), scale);
    for (const auto& [j, w] : row) {
      if (unknown[size_t(j)] != kNone) entries.emplace_back(Eigen::Index(r), Eigen::Index(unknown[size_t(j)]), -scale * w);
      else
        for (int c = 0; c < 2; ++c) s.b(Eigen::Index(r), c) += scale * w * uv[size_t(2 * j + c)];
    }
  }
  s.A.setFromTriplets(entries.begin(), entries.end());
  return s;
}

template <class Solver>
Eigen::MatrixXd solve_with(Solver& solver, const System& s, const std::string& source) {
  solver.compute(s.A);
  if (solver.info() != Eigen::Success)
    throw Error(fmt::format("{}: the Tutte system could not be factored (degenerate weights)", source));
  Eigen::MatrixXd x = solver.solve(s.b);
  if (solver.info() != Eigen::Success || !x.allFinite())
    throw Error(fmt::format("{}: the Tutte system could not be solved (degenerate weights)", source));
  return x;
}

}  // namespace

std::vector<std::pair<Index, double>> tutte_row(const Level& level, std::span<const double> positions, Index v,
                                                TutteWeights weights) {
  std::vector<std::pair<Index, double>> row;
  if (weights == TutteWeights::MeanValue) row = mean_value_row(level, positions, v);
  else
    for (Index e : level.ring_edges(v)) add(row, level.other_end(e, v), 1.0);
  normalise(row, v);
  return row;
}

TutteResult tutte_embedding(const Level& level, std::span<const double> positions, const TutteOptions& options,
                            const std::string& source) {
  TutteResult out;
  out.boundary = disc_boundary_loop(level, source);
  out.uv.assign(size_t(2 * level.vertex_count), 0.0);
  if (options.boundary == BoundaryShape::Circle) circle_layout(out.boundary, positions, out.uv);
  else out.corners = square_layout(out.boundary, positions, options.corners, out.uv, source);
  std::vector<Index> unknown(size_t(level.vertex_count), kNone), interior;
  for (Index v = 0; v < level.vertex_count; ++v)
    if (!level.on_boundary(v)) unknown[size_t(v)] = Index(interior.size()), interior.push_back(v);
  if (interior.empty()) return out;
  const System s = build_system(level, positions, unknown, interior, out.uv, options.weights);
  Eigen::MatrixXd x;
  if (options.weights == TutteWeights::Uniform) {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    x = solve_with(solver, s, source);
  } else {
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
    x = solve_with(solver, s, source);
  }
  for (size_t r = 0; r < interior.size(); ++r)
    for (int c = 0; c < 2; ++c) out.uv[size_t(2 * interior[r] + c)] = x(Eigen::Index(r), c);
  return out;
}

}  // namespace subdiv
