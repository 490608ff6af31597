#pragma once
// The local subdivision matrix S of a rotationally symmetric neighbourhood split by the
// discrete Fourier transform. Around an interior vertex of valence n whose surroundings are
// n equal sectors, a rotation by one sector permutes the labels (the centre fixed, every
// other label in an orbit of n) and S commutes with it, so S is block-circulant: in the basis
// of the rotation's eigenvectors it falls into one block per frequency k = 0..n-1, of the
// size of one sector (Doo & Sabin 1978, "Behaviour of recursive division surfaces near
// extraordinary points"; Ball & Storry 1988, "Conditions for tangent plane continuity over
// recursively generated B-spline surfaces"; Stam 1998 computes Catmull-Clark's
// eigen-structure this way). Eigenvalues and eigenvectors of S are those of the blocks,
// lifted: a valence-360 vertex costs 181 blocks of a few rows instead of a dense
// eigen-decomposition of thousands.
//
// Nothing here knows a scheme: the rotation comes from the labelling (local_patch.h) and is
// checked on the numbers (S[turn i][turn j] = S[i][j]) before it is used.
#include <Eigen/Dense>
#include <complex>
#include <optional>
#include <utility>
#include <vector>

namespace subdiv {

// S over labels 0..m-1 as sparse rows: row i (a child label) lists (parent label, weight).
using LocalRows = std::vector<std::vector<std::pair<int, double>>>;

class RotationBlocks {
public:
  // The split of S, or nothing when `turn` (label -> the label of its image under one
  // rotation) is not a permutation of 0..m-1 whose orbits are fixed labels and orbits of
  // exactly n, or when S does not commute with it (to `tolerance`, absolute).
  static std::optional<RotationBlocks> split(const LocalRows& s, const std::vector<int>& turn, int n,
                                             double tolerance = 1e-12);

  int size() const { return m_; }
  // All m eigenvalues of S (in no particular order).
  std::vector<std::complex<double>> eigenvalues() const;
  // Orthonormal real bases of the null spaces of S - lambda I and of S^T - lambda I (m
  // rows): singular values of the blocks at most `relative` times max(1, the largest
  // singular value of S - lambda I) count as zero, as a dense SVD of S - lambda I decides.
  Eigen::MatrixXd right_null(double lambda, double relative) const;
  Eigen::MatrixXd left_null(double lambda, double relative) const;

private:
  Eigen::MatrixXd null_space(double lambda, double relative, bool left) const;
  // Block k's vector y lifted to the labels: fixed labels y_f (k = 0 only), orbit t at its
  // shift s: y_t w^(-k s) / sqrt(n), w = exp(2 pi i / n).
  Eigen::VectorXcd lift(int k, const Eigen::VectorXcd& y) const;
  bool self_conjugate(int k) const { return k == 0 || 2 * k == n_; }

  int n_ = 0, m_ = 0;
  std::vector<int> fixed_;                // labels the rotation fixes
  std::vector<std::vector<int>> orbits_;  // orbit t: r_t, turn(r_t), turn^2(r_t), ...
  std::vector<Eigen::MatrixXcd> blocks_;  // k = 0..n/2; block n-k is block k's conjugate
};

}  // namespace subdiv
