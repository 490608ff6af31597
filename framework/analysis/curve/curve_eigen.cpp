#include "framework/analysis/curve/curve_eigen.h"

#include "framework/util/error.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>

namespace subdiv {

namespace {

using Matrix = Eigen::MatrixXd;
using Vector = Eigen::VectorXd;

constexpr double kRealTolerance = 1e-9;     // |imaginary part| below this counts as real
constexpr double kNullTolerance = 1e-6;     // singular values below this (relative) are zero
constexpr double kSnap = 1e-14;             // mask weights below this (relative) print as 0

Matrix to_eigen(const LocalSubdivisionMatrix& s) {
  const int n = s.size();
  Matrix out(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) out(i, j) = s.rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  return out;
}

std::vector<std::complex<double>> sorted_eigenvalues(const Matrix& s) {
  Eigen::EigenSolver<Matrix> solver(s, /*computeEigenvectors=*/false);
  if (solver.info() != Eigen::Success)
    throw Error("curve analysis: the eigenvalue solver did not converge on the local subdivision matrix");
  std::vector<std::complex<double>> values(solver.eigenvalues().data(),
                                           solver.eigenvalues().data() + solver.eigenvalues().size());
  std::sort(values.begin(), values.end(), [](auto x, auto y) {
    if (std::abs(x) != std::abs(y)) return std::abs(x) > std::abs(y);
    if (x.real() != y.real()) return x.real() > y.real();
    return x.imag() > y.imag();
  });
  return values;
}

// Left eigenvector of the real eigenvalue lambda (x S = lambda x, Zorin et al. 2000): the null
// vector of S^T - lambda I. None unless that null space is exactly one-dimensional.
std::optional<Vector> left_eigenvector(const Matrix& s, double lambda) {
  const Eigen::Index n = s.rows();
  const Matrix a = s.transpose() - lambda * Matrix::Identity(n, n);
  Eigen::JacobiSVD<Matrix> svd(a, Eigen::ComputeFullV);
  const Vector& sigma = svd.singularValues();  // descending
  const double scale = std::max(1.0, sigma(0));
  if (sigma(n - 1) > kNullTolerance * scale) return std::nullopt;
  if (n >= 2 && sigma(n - 2) <= kNullTolerance * scale) return std::nullopt;
  return Vector(svd.matrixV().col(n - 1));
}

std::vector<double> snapped(const Vector& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  std::vector<double> out(v.data(), v.data() + v.size());
  for (double& x : out)
    if (std::abs(x) <= kSnap * largest) x = 0.0;
  return out;
}

bool has_dominant_one(const std::vector<std::complex<double>>& ev) {
  if (ev.empty() || std::abs(ev[0] - 1.0) > kRealTolerance) return false;
  return ev.size() == 1 || std::abs(ev[1]) < 1.0 - kRealTolerance;
}

// 1 = lambda_0 > |lambda_1| > |lambda_2|, lambda_1 real and non-zero (Halstead, Kass & DeRose 1993).
bool has_simple_subdominant(const std::vector<std::complex<double>>& ev) {
  if (!has_dominant_one(ev) || ev.size() < 2) return false;
  const auto l1 = ev[1];
  if (std::abs(l1.imag()) > kRealTolerance || std::abs(l1) <= kRealTolerance) return false;
  return ev.size() == 2 || std::abs(l1) - std::abs(ev[2]) > kEigenTieTolerance;
}

void add_limit_mask(const Matrix& s, LocalEigenAnalysis& out) {
  if (!has_dominant_one(out.eigenvalues)) return;
  const auto v = left_eigenvector(s, 1.0);
  if (!v || std::abs(v->sum()) <= 1e-12 * v->cwiseAbs().sum()) return;
  out.limit_mask = snapped(*v / v->sum());  // affine weights: they sum to 1
  out.has_limit_mask = true;
}

void add_tangent_mask(const Matrix& s, int first_index, LocalEigenAnalysis& out) {
  if (!has_simple_subdominant(out.eigenvalues)) return;
  const auto v = left_eigenvector(s, out.eigenvalues[1].real());
  if (!v) return;
  // Scale to return 1 on the data P_j = j (derivative per unit old parameter).
  double on_identity = 0.0;
  for (Eigen::Index j = 0; j < v->size(); ++j) on_identity += (*v)(j) * static_cast<double>(first_index + j);
  if (std::abs(on_identity) <= 1e-12 * v->cwiseAbs().sum()) return;
  out.tangent_mask = snapped(*v / on_identity);
  out.has_tangent_mask = true;
}

bool ties(double x, double y) { return std::abs(x - y) <= kEigenTieTolerance; }

// The four cases of lambda_1^2 against |lambda_2| (Peters & Reif 2004's argument, for curves).
std::string indication(const std::vector<std::complex<double>>& ev) {
  if (!has_simple_subdominant(ev)) return "";
  const double square = ev[1].real() * ev[1].real();
  const double l2 = ev.size() > 2 ? std::abs(ev[2]) : 0.0;
  const double l3 = ev.size() > 3 ? std::abs(ev[3]) : 0.0;
  if (ties(square, l2))
    return ties(l2, l3) ? "lambda1^2 = |lambda2| = |lambda3|: C1 at best, curvature may diverge"
                        : "lambda1^2 = |lambda2| > |lambda3|: C2 possible, curvature continuous";
  return square < l2 ? "lambda1^2 < |lambda2|: C1 at best, curvature unbounded"
                     : "lambda1^2 > |lambda2|: C2 possible, curvature tends to zero";
}

}  // namespace

LocalEigenAnalysis analyse_local_matrix(const LocalSubdivisionMatrix& matrix) {
  LocalEigenAnalysis out;
  if (matrix.size() == 0) return out;
  const Matrix s = to_eigen(matrix);
  out.eigenvalues = sorted_eigenvalues(s);
  if (out.eigenvalues.size() >= 2) out.subdominant = out.eigenvalues[1];
  add_limit_mask(s, out);
  add_tangent_mask(s, matrix.first_index, out);
  out.indication = indication(out.eigenvalues);
  return out;
}

}  // namespace subdiv
