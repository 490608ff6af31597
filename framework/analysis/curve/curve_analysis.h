#pragma once
// Convergence and smoothness of a linear, stationary curve scheme of any arity m from its
// symbol (Dyn, Gregory & Levin 1991; Dyn 1992), plus the eigen-analysis of its local subdivision matrix
// (Zorin et al. 2000).
//
// The difference scheme. With F(z; f) = sum_j f_j z^j, one step is F(z; S_a f) =
// a(z) F(z^m; f) (Dyn, Gregory & Levin 1991) and F(z; Δf) = (1 - z) F(z; f). Because
// 1 - z^m = (1 - z) σ(z) with σ(z) = 1 + z + ... + z^{m-1}, a(z) = σ(z) q(z) gives
// Δ(S_a f) = S_q Δf: Dyn, Gregory & Levin 1991 for m = 2, and the same computation for any m.
// S_a converges iff a(1) = m, σ divides a, and S_q is contractive (Dyn, Gregory & Levin 1991;
// N. Dyn, D. Levin, "Subdivision schemes in geometric modelling", Acta Numerica 11 (2002)
// 73-144, §4 for m = 2; M.F. Hassan, I.P. Ivrissimtzis, N.A. Dodgson, M.A. Sabin, "An
// interpolating 4-point C2 ternary stationary subdivision scheme", CAGD 19 (2002) 1-18,
// §3, who write it as contractivity of (1/3) S_b, b(z) = 3 a(z)/(1 + z + z^2), for m = 3).
// No factor m here: q = a/σ is the scheme of the plain differences.
//
// Smoothness. The divided differences m^k Δf^k obey m^{k+1} Δf^{k+1} = S_{m a/σ}(m^k Δf^k),
// so with a(z) = (σ(z)/m)^k b_k(z) the scheme S_a is C^k when S_{b_k} converges
// (Dyn, Gregory & Levin 1991 for m = 2, where σ/m = (1+z)/2). b_k(1) = a(1) = m, so S_{b_k}
// converges when σ divides b_k and q_k = b_k/σ is contractive. Level k of this file is
// that test; level 0 is convergence itself.
#include "framework/analysis/curve/curve_contractivity.h"
#include "framework/analysis/curve/curve_eigen.h"
#include "framework/analysis/curve/curve_laurent.h"
#include "framework/analysis/curve/curve_local_matrix.h"
#include "framework/analysis/curve/curve_mask.h"

#include <complex>
#include <string>
#include <vector>

namespace subdiv {

// A necessary condition for convergence (Dyn, Gregory & Levin 1991): a(1) = m and
// a(w^k) = 0 for w = exp(2 pi i/m), k = 1 .. m-1 (for m = 2: a(-1) = 0).
struct NecessaryCondition {
  std::string name;               // "a(1)", "a(-1)", "a(w)", "a(w^2)", ...
  std::complex<double> value;
  double expected = 0.0;
  bool holds = false;
};

// Level k: a(z) = (σ(z)/m)^k b_k(z); proven() means S_a is C^k.
struct SmoothnessLevel {
  int order = 0;                         // k
  bool factor_divides = false;           // σ divides b_k (else stop: no level k or beyond)
  double remainder = 0.0;                // relative remainder of that division
  LaurentPolynomial difference_symbol;   // q_k = b_k / σ, when factor_divides
  ContractivitySearch contractivity;     // of S_{q_k}

  bool proven() const { return factor_divides && contractivity.contractive; }
};

struct CurveAnalysisOptions {
  ContractivityOptions contractivity;    // max_power L = 10 by default
  double division_tolerance = 1e-12;     // exact division: remainder <= this * sum |p_i|
  double condition_tolerance = 1e-12;    // necessary conditions: |a(w^k) - target| <= this * sum |a_i|
};

struct CurveAnalysis {
  CurveMask mask;
  LaurentPolynomial symbol;                       // a(z)
  std::vector<NecessaryCondition> conditions;     // a(1), then a(w^k), k = 1 .. m-1
  std::vector<double> sub_mask_sums;              // sum of a_{r + m j} over j, r = 0 .. m-1
  bool necessary_conditions_hold = false;

  // Levels 0, 1, ... while σ keeps dividing; empty if the necessary conditions fail.
  std::vector<SmoothnessLevel> levels;
  bool convergent = false;                        // proven: level 0 contractive
  int smoothness = -1;                            // largest k with C^k proven; -1 if none
  int max_power = 10;                             // the L searched (CurveAnalysisOptions)

  LocalSubdivisionMatrix local_matrix;
  LocalEigenAnalysis eigen;

};

// Throws subdiv::Error on an invalid mask (see validate()) or options.
CurveAnalysis analyse_curve(const CurveMask& mask, const CurveAnalysisOptions& options = {});

}  // namespace subdiv
