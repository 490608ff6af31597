#pragma once
// Progressive iterative interpolation (Chen et al. 2008 for Catmull-Clark; local form:
// Zhao, Lin, Bao 2012; with shape control: Lin et al. 2015) for any linear limit operator L:
//
//   D^k = V^0 - L V^k                    (targets V^0 are the initial control points)
//   V_P^{k+1} = V_P^k + D_P^k,  V_Q^{k+1} = V_Q^k
//
// P the moving vertices, Q the fixed ones. It converges when the eigenvalues of L_PP lie in
// (0, 2); for Catmull-Clark, Loop and Lin et al. 2015's two-step scheme (lambda in (7/20, 1]) they
// lie in (0, 1] (L_PP = C D, C diagonal positive, D symmetric positive definite). The
// residual reported is |D_v^k| over the moving vertices.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "framework/interpolation/limit_evaluator.h"

namespace subdiv {

struct IterationRecord {
  int iteration = 0;        // k: the residual of V^k, before its update
  double max_residual = 0;  // max over moving vertices of |V^0_v - (L V^k)_v|
  double rms_residual = 0;  // root mean square of the same
};

// What an observer sees after each residual evaluation: V^k, L V^k and the record.
struct IterationState {
  const IterationRecord& record;
  std::span<const double> control;
  std::span<const double> limit;
};

struct ProgressiveOptions {
  double tolerance = 1e-10;  // stop once max_residual <= tolerance (model units)
  int max_iterations = 1000;  // updates at most; the result then has converged = false
  int channels = 3;
  std::function<void(const IterationState&)> observer;  // progress, tests
};

struct ProgressiveResult {
  std::vector<double> control;           // V^K, channels per vertex
  std::vector<double> limit;             // L V^K for every vertex
  std::vector<IterationRecord> history;  // k = 0 .. K
  int iterations = 0;                    // K, the number of updates made
  bool converged = false;
};

// `limit` maps control points to limit points (rows and sources: the vertices). `moving`
// has one flag per vertex (nonzero: moving); empty means all move. Throws subdiv::Error for
// mismatched sizes, an empty moving set, non-finite targets, and when the residual grows a
// millionfold (the operator's eigenvalues on the moving set leave (0, 2)).
ProgressiveResult progressive_interpolation(const StencilTable& limit, std::span<const double> targets,
                                            std::span<const std::uint8_t> moving,
                                            const ProgressiveOptions& options = {});
ProgressiveResult progressive_interpolation(const LimitEvaluator& evaluator, const Level& level,
                                            std::span<const double> targets, std::span<const std::uint8_t> moving,
                                            const ProgressiveOptions& options = {});

// Theorem 2 of Lin et al. 2015 for any limit operator: the final offsets of the fixed vertices,
//   D_Q^inf = D_Q^0 - L_QP L_PP^-1 D_P^0,  D^0 = V^0 - L V^0,
// channels per vertex (zeros on moving vertices). Throws subdiv::Error when L_PP is singular.
std::vector<double> predicted_fixed_offsets(const StencilTable& limit, std::span<const double> targets,
                                            std::span<const std::uint8_t> moving, int channels = 3);

// The tolerance used when none is given: 1e-10 of the diagonal of the targets' bounding
// box (xyz per vertex), so that it scales with the model's units.
double default_interpolation_tolerance(std::span<const double> targets);

// The moving set from a user's text: "all", a list of 0-based ids separated by commas or
// white space, '#' starting a comment. Repeated ids count once. Throws subdiv::Error naming
// `source` and the bad entry: not a number, negative, or >= vertex_count.
std::vector<std::uint8_t> parse_vertex_selection(const std::string& text, Index vertex_count,
                                                 const std::string& source);

}  // namespace subdiv
