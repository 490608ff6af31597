#pragma once
// Seed 001 (Lin, Pan, Chen, Huang): shape-controlled two-step Catmull-Clark and its
// progressive interpolation.
//
// Step one refines with Catmull-Clark's face and edge points and the vertex rule
//   v' = lambda v + (1 - lambda)(alpha E + (1 - alpha) F),  alpha = 10/13,
// E the mean of the edge neighbours, F the mean of the vertices opposite v in its quads
// (schemes/catmull-clark-shape.json); every later step is plain Catmull-Clark. lambda may
// differ per vertex and must lie in (7/20, 1].
//
// Formula (2): the limit point of an old vertex v of valence n (closed quad mesh) is
//   v_inf = ((n^2 lambda + 7n/4) v + beta_n sum e_j + (3/10) beta_n sum f_j) / (n (n + 5)),
//   beta_n = n (1 - lambda) 10/13 + 5/2,
// Catmull-Clark's limit mask (seed 000) applied to the level-1 mesh and expanded.
//
// Theorem 2, derived again. Let L be the limit operator (rows of formula (2)), P the moving
// and Q the fixed vertices, D^k = V^0 - L V^k for every vertex. The iteration moves
// V_P^{k+1} = V_P^k + D_P^k and keeps V_Q, so
//   D^{k+1} = V^0 - L V^{k+1} = D^k - L_{*P} D_P^k,
// i.e. D_P^{k+1} = (I - M) D_P^k with M = L_PP (the paper's (15)), and
//   D_Q^{k+1} = D_Q^k - E D_P^k  with E = L_QP:  e_qp = G(V_q, V_p) beta_{n_q} / (n_q (n_q + 5)),
// the weight of moving vertex p in fixed vertex q's limit mask (the valence is q's). The
// paper's (21) writes "+ E D_P^k" and its proof ends in "+ E M^-1 D_P^0": that is the sign
// slip. Summing the geometric series, with the eigenvalues of M in (0, 1]:
//   D_Q^inf = D_Q^0 - E sum_k (I - M)^k D_P^0 = D_Q^0 - E M^-1 D_P^0,
// the theorem as stated. The fixed vertices stay put; their limit points end at
// V_Q^0 - D_Q^inf. predicted_fixed_offsets (progressive.h) evaluates this for any L.
#include <span>
#include <vector>

#include "framework/interpolation/limit_evaluator.h"
#include "framework/interpolation/progressive.h"
#include "framework/refine/child_origins.h"
#include "framework/features/feature_context.h"

namespace subdiv {

inline constexpr double kShapeAlpha = 10.0 / 13.0;
inline constexpr double kShapeLambdaMin = 7.0 / 20.0;  // exclusive
inline constexpr double kShapeLambdaMax = 1.0;         // inclusive

// Throws subdiv::Error unless every value lies in (7/20, 1]; `what` names the source
// ("--lambda", "lambda.txt line 4", ...). One value, or one per vertex (vertex_count).
void check_shape_lambda(std::span<const double> lambda, Index vertex_count, const std::string& what = "lambda");

// Formula (2) with lambda per vertex (one value applies to all). Interior vertices of
// closed quad meshes, as in the paper; anything else is refused with the vertex named
// (limit_selection.h's composite limit covers boundaries and other polygons).
class ShapeTwoStepLimit final : public LimitEvaluator {
public:
  explicit ShapeTwoStepLimit(double lambda);
  explicit ShapeTwoStepLimit(std::vector<double> lambda_per_vertex);
  std::string name() const override;
  double lambda(Index v) const { return lambda_.size() == 1 ? lambda_[0] : lambda_[v]; }

protected:
  StencilTable stencils_at(const Level& level, int step) const override;  // the base mesh (step ignored)

private:
  std::vector<double> lambda_;
};

// The first step's stencils with lambda per vertex: `engine_step` (the table the engine
// built for the shape scheme at any lambda; face and edge points and feature rules are
// kept) with the rows of the smooth vertices' children rewritten by the vertex rule above.
// `origins` are the step's child origins, `base` its parent level.
StencilTable shape_first_step(const Level& base, const ChildOrigins& origins, const StencilTable& engine_step,
                              std::span<const double> lambda, const FeatureOptions& features = {});

// Seed 001's method in one call: formula (2), global (moving empty: all vertices) or local
// progressive interpolation of `targets` (xyz per vertex, also the initial control points).
ProgressiveResult shape_progressive_interpolation(const Level& closed_quads, std::span<const double> targets,
                                                  std::span<const double> lambda,
                                                  std::span<const std::uint8_t> moving,
                                                  const ProgressiveOptions& options = {});

}  // namespace subdiv
