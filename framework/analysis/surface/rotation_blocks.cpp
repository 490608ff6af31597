#include "framework/analysis/surface/rotation_blocks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace subdiv {
namespace {

using Complex = std::complex<double>;
constexpr double kWeightZero = 1e-14;  // weights below this are no dependence

const double kPi = std::acos(-1.0);

// The rows sorted by column, without the weights that are no dependence.
LocalRows sorted_rows(const LocalRows& s) {
  LocalRows out(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    for (const auto& [j, w] : s[i])
      if (std::abs(w) > kWeightZero) out[i].emplace_back(j, w);
    std::sort(out[i].begin(), out[i].end());
  }
  return out;
}

// S[turn i][turn j] = S[i][j] for every entry, and no entry more.
bool commutes(const LocalRows& sorted, const std::vector<int>& turn, double tolerance) {
  for (size_t i = 0; i < sorted.size(); ++i) {
    const auto& image = sorted[size_t(turn[i])];
    if (image.size() != sorted[i].size()) return false;
    for (const auto& [j, w] : sorted[i]) {
      const int tj = turn[size_t(j)];
      const auto it = std::lower_bound(image.begin(), image.end(), std::make_pair(tj, -1e300));
      if (it == image.end() || it->first != tj || std::abs(it->second - w) > tolerance) return false;
    }
  }
  return true;
}

}  // namespace

std::optional<RotationBlocks> RotationBlocks::split(const LocalRows& s, const std::vector<int>& turn, int n,
                                                    double tolerance) {
  const int m = int(s.size());
  if (n < 2 || int(turn.size()) != m) return std::nullopt;
  std::vector<int> hits(size_t(m), 0);
  for (int t : turn) {
    if (t < 0 || t >= m || hits[size_t(t)]++) return std::nullopt;  // not a permutation
  }
  RotationBlocks b;
  b.n_ = n, b.m_ = m;
  std::vector<char> seen(static_cast<size_t>(m), 0);
  for (int i = 0; i < m; ++i) {
    if (seen[size_t(i)]) continue;
    std::vector<int> cycle;
    for (int j = i; !seen[size_t(j)]; j = turn[size_t(j)]) seen[size_t(j)] = 1, cycle.push_back(j);
    if (cycle.size() == 1) b.fixed_.push_back(i);
    else if (int(cycle.size()) == n) b.orbits_.push_back(std::move(cycle));
    else return std::nullopt;
  }
  for (const auto& row : s)
    for (const auto& [j, w] : row)
      if (j < 0 || j >= m) return std::nullopt;
  const LocalRows sorted = sorted_rows(s);
  if (!commutes(sorted, turn, tolerance)) return std::nullopt;

  // Where each label sits: a fixed label's index, or its orbit and shift.
  const int F = int(b.fixed_.size()), T = int(b.orbits_.size());
  std::vector<int> fixed_of(size_t(m), -1), orbit_of(size_t(m), -1), shift_of(size_t(m), 0);
  for (int f = 0; f < F; ++f) fixed_of[size_t(b.fixed_[size_t(f)])] = f;
  for (int t = 0; t < T; ++t)
    for (int sh = 0; sh < n; ++sh) {
      const size_t label = size_t(b.orbits_[size_t(t)][size_t(sh)]);
      orbit_of[label] = t, shift_of[label] = sh;
    }
  // w^(-j) for j = 0..n-1.
  std::vector<Complex> phase(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) phase[size_t(j)] = std::polar(1.0, -2 * kPi * double(j) / double(n));
  const double root = std::sqrt(double(n));
  // In the orthonormal basis (fixed labels; per orbit t, q_t = sum_s w^(-k s) e_{turn^s r_t} / sqrt(n)):
  // B_k[t][t'] = sum_s w^(-k s) S[r_t][turn^s r_t'], and at k = 0 the fixed labels' rows and
  // columns. Only the orbits' first rows and the fixed rows are read.
  for (int k = 0; 2 * k <= n; ++k) {
    const int off = k == 0 ? F : 0;
    Eigen::MatrixXcd B = Eigen::MatrixXcd::Zero(off + T, off + T);
    auto add_row = [&](int row, int from_label) {
      for (const auto& [j, w] : sorted[size_t(from_label)]) {
        if (fixed_of[size_t(j)] >= 0) {
          if (k == 0) B(row, fixed_of[size_t(j)]) += w * (row < off ? 1.0 : root);
          continue;
        }
        B(row, off + orbit_of[size_t(j)]) += w * phase[size_t((std::int64_t(k) * shift_of[size_t(j)]) % n)];
      }
    };
    if (k == 0)
      for (int f = 0; f < F; ++f) add_row(f, b.fixed_[size_t(f)]);
    for (int t = 0; t < T; ++t) add_row(off + t, b.orbits_[size_t(t)][0]);
    // A fixed row against an orbit: sum over the orbit / sqrt(n) (add_row summed it with phases).
    if (k == 0)
      for (int f = 0; f < F; ++f) B.row(f).tail(T) /= root;
    b.blocks_.push_back(std::move(B));
  }
  return b;
}

std::vector<std::complex<double>> RotationBlocks::eigenvalues() const {
  std::vector<Complex> out;
  out.reserve(size_t(m_));
  for (int k = 0; k < int(blocks_.size()); ++k) {
    const Eigen::MatrixXcd& B = blocks_[size_t(k)];
    if (B.rows() == 0) continue;
    if (self_conjugate(k)) {
      Eigen::EigenSolver<Eigen::MatrixXd> solver(B.real(), false);
      for (Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i) out.push_back(solver.eigenvalues()(i));
      continue;
    }
    Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver(B, false);
    for (Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i) {
      const Complex z = solver.eigenvalues()(i);
      out.push_back(z), out.push_back(std::conj(z));  // block n - k is the conjugate
    }
  }
  return out;
}

Eigen::VectorXcd RotationBlocks::lift(int k, const Eigen::VectorXcd& y) const {
  Eigen::VectorXcd v = Eigen::VectorXcd::Zero(m_);
  const int off = k == 0 ? int(fixed_.size()) : 0;
  for (int f = 0; f < off; ++f) v(fixed_[size_t(f)]) = y(f);
  const double root = std::sqrt(double(n_));
  for (size_t t = 0; t < orbits_.size(); ++t)
    for (int s = 0; s < n_; ++s) {
      const double angle = -2 * kPi * double((std::int64_t(k) * s) % n_) / double(n_);
      v(orbits_[t][size_t(s)]) = y(off + Eigen::Index(t)) * std::polar(1.0, angle) / root;
    }
  return v;
}

Eigen::MatrixXd RotationBlocks::null_space(double lambda, double relative, bool left) const {
  // Per block: singular values and the singular vectors (U for left, V for right). A
  // self-conjugate block is real: its real SVD gives real null vectors.
  struct Svd {
    Eigen::VectorXd sigma;
    Eigen::MatrixXcd vectors;
  };
  std::vector<Svd> svds;
  double largest = 0;
  for (int k = 0; k < int(blocks_.size()); ++k) {
    const Eigen::MatrixXcd& B = blocks_[size_t(k)];
    Svd s;
    if (B.rows() == 0) {  // no orbits (the centre alone): nothing at this frequency
      svds.push_back(std::move(s));
      continue;
    }
    const unsigned options = Eigen::ComputeFullU | Eigen::ComputeFullV;
    if (self_conjugate(k)) {
      const Eigen::MatrixXd M = B.real() - lambda * Eigen::MatrixXd::Identity(B.rows(), B.cols());
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, options);
      s.sigma = svd.singularValues();
      s.vectors = (left ? svd.matrixU() : svd.matrixV()).cast<Complex>();
    } else {
      const Eigen::MatrixXcd M = B - lambda * Eigen::MatrixXcd::Identity(B.rows(), B.cols());
      Eigen::JacobiSVD<Eigen::MatrixXcd> svd(M, options);
      s.sigma = svd.singularValues();
      s.vectors = left ? svd.matrixU() : svd.matrixV();
    }
    if (s.sigma.size()) largest = std::max(largest, s.sigma(0));
    svds.push_back(std::move(s));
  }
  const double limit = relative * std::max(1.0, largest);
  std::vector<Eigen::VectorXd> basis;
  for (int k = 0; k < int(blocks_.size()); ++k) {
    const Svd& s = svds[size_t(k)];
    for (Eigen::Index i = 0; i < s.sigma.size(); ++i) {
      if (s.sigma(i) > limit) continue;
      // Right: S v = lambda v for v = lift(V_i). Left: (S - lambda)^H u = 0 for u = lift(U_i),
      // and the real and imaginary parts of u are real left eigenvectors (S, lambda real).
      // A block k off the real axis stands for itself and block n - k (its conjugate): the
      // two parts of the lifted vector span both, orthogonal and of equal norm.
      const Eigen::VectorXcd v = lift(k, s.vectors.col(i));
      if (self_conjugate(k)) {
        basis.push_back(v.real().normalized());
        continue;
      }
      basis.push_back(v.real().normalized());
      basis.push_back(v.imag().normalized());
    }
  }
  Eigen::MatrixXd out(m_, Eigen::Index(basis.size()));
  for (size_t c = 0; c < basis.size(); ++c) out.col(Eigen::Index(c)) = basis[c];
  return out;
}

Eigen::MatrixXd RotationBlocks::right_null(double lambda, double relative) const {
  return null_space(lambda, relative, false);
}
Eigen::MatrixXd RotationBlocks::left_null(double lambda, double relative) const {
  return null_space(lambda, relative, true);
}

}  // namespace subdiv
