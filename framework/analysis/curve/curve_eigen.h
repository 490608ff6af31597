#pragma once
// Eigen-analysis of a curve scheme's local subdivision matrix (Zorin et al. 2000): the
// spectrum, the limit mask (left eigenvector of 1) and the tangent mask (left eigenvector
// of the subdominant eigenvalue).
#include "framework/analysis/curve/curve_local_matrix.h"

#include <complex>
#include <string>
#include <vector>

namespace subdiv {

struct LocalEigenAnalysis {
  // All eigenvalues, sorted by modulus descending (ties: larger real part first). Defective
  // eigenvalues (incomplete eigenvectors, e.g. interpolatory 4-point masks) carry round-off
  // of order 1e-8 and may show a tiny imaginary part.
  std::vector<std::complex<double>> eigenvalues;

  // Halstead, Kass & DeRose 1993: if lambda_0 = 1 > |lambda_i|, the limit point of the centre is
  // limit_mask . P over the neighbourhood points (weights sum to 1).
  bool has_limit_mask = false;
  std::vector<double> limit_mask;

  // Halstead, Kass & DeRose 1993: if 1 > |lambda_1| > |lambda_2| with lambda_1 real, the tangent at the
  // limit point is tangent_mask . P. It is scaled so that tangent_mask . (j)_j = 1, i.e. it
  // returns the derivative per unit of the old parameter for a scheme with linear
  // precision (on data P_j = j it gives 1).
  bool has_tangent_mask = false;
  std::complex<double> subdominant = 0.0;   // lambda_1 when there are at least 2 eigenvalues
  std::vector<double> tangent_mask;

  // Curvature (Peters & Reif 2004's argument, for curves): lambda_1^2 against |lambda_2| and
  // |lambda_3|. An indication, not a proof; empty when lambda_1 is not a simple real one.
  std::string indication;
};

// Eigenvalues relative to the largest one equal within this tolerance are treated as equal.
inline constexpr double kEigenTieTolerance = 1e-6;

LocalEigenAnalysis analyse_local_matrix(const LocalSubdivisionMatrix& matrix);

}  // namespace subdiv
