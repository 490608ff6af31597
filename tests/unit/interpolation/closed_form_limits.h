#pragma once
// Test references: closed-form limit masks (Halstead, Kass & DeRose 1993, Loop 1987, Kobbelt 2000) written out by hand,
// to check the masks the engine derives from each scheme's eigen-analysis
// (framework/interpolation/analysed_limit.h) against formulas computed elsewhere.
//
// Features follow the engine's classification (rules/feature_context.h, DeRose et al.
// 1998): boundary edges and tags of sharpness >= 10 are infinitely sharp; a vertex on two
// such edges is a crease vertex and its limit is the cubic B-spline's, (1/6, 2/3, 1/6)
// along the crease; a corner (three or more sharp edges, a sharp vertex tag, a boundary
// corner under edges-and-corners) stays where it is. Darts and semi-sharp features have
// no closed form here; the evaluators refuse them with the vertex named.
#include "framework/interpolation/limit_evaluator.h"
#include "framework/features/feature_context.h"

namespace subdiv::test {

// Catmull-Clark. Interior vertex of valence n among quads (Halstead, Kass & DeRose 1993):
//   v_inf = (n^2 v + 4 sum e_j + sum f_j) / (n (n + 5)),
// e_j the edge neighbours, f_j the vertex opposite v in quad j. Among polygons of any
// size, one Catmull-Clark step (face centroids c_j, edge points, vertex point) makes the
// 1-ring quads and the same mask expands to
//   v_inf = (n (n - 1) v + 2 sum e_j + 4 sum c_j) / (n (n + 5)),
// which is their formula when every face is a quad (4 c_j = v + e_j + e_{j+1} + f_j).
class CatmullClarkLimit final : public LimitEvaluator {
public:
  explicit CatmullClarkLimit(FeatureOptions features = {}) : features_(features) {}
  std::string name() const override { return "Catmull-Clark closed form (Halstead, Kass & DeRose 1993)"; }

protected:
  StencilTable stencils_at(const Level& level, int step) const override;

private:
  FeatureOptions features_;
};

// Loop with vertex rule (1 - n beta_n) v + beta_n sum e_j. Loop 1987 gives the limit as
//   v_inf = gamma_n v + (1 - gamma_n) (1/n) sum e_j,  gamma_n = 3 / (11 - 8 beta_bar_n),
// beta_bar_n = 1 - n beta_n the vertex's own weight; equivalently gamma_n = 3 / (3 + 8 n beta_n).
// Triangles only.
enum class LoopBeta { Loop, Warren };  // Loop 1987's beta_n; Warren's 3/16 (n = 3), 3/(8n)
double loop_beta(LoopBeta variant, int n);

class LoopLimit final : public LimitEvaluator {
public:
  explicit LoopLimit(LoopBeta beta = LoopBeta::Loop, FeatureOptions features = {})
      : beta_(beta), features_(features) {}
  std::string name() const override;
  LoopBeta beta() const { return beta_; }

protected:
  StencilTable stencils_at(const Level& level, int step) const override;

private:
  LoopBeta beta_;
  FeatureOptions features_;
};

// Kobbelt's sqrt(3) with vertex rule (1 - a_n) v + (a_n / n) sum e_j, a_n = (4 - 2 cos(2 pi/n))/9:
//   v_inf = (1 - b_n) v + (b_n / n) sum e_j,  b_n = 3 a_n / (1 + 3 a_n)
// (invariant because one step makes the ring out of the face points (v + e_j + e_{j+1})/3).
// Interior vertices and corners only: sqrt(3)'s boundaries are trisected every second step
// and are left to the engine's analysed masks.
class Sqrt3Limit final : public LimitEvaluator {
public:
  explicit Sqrt3Limit(FeatureOptions features = {}) : features_(features) {}
  std::string name() const override { return "sqrt(3) closed form (Kobbelt 2000)"; }

protected:
  StencilTable stencils_at(const Level& level, int step) const override;

private:
  FeatureOptions features_;
};

}  // namespace subdiv::test
