#pragma once
// Limit masks from the scheme's own eigen-analysis (framework/analysis/surface/limit_evaluation.h,
// Halstead, Kass & DeRose 1993: the left eigenvector of eigenvalue 1 of the local subdivision
// matrix), for any linear scheme with vertex points: the shipped ones, JSON schemes users
// write and plugin schemes alike. Darts, creases, corners and semi-sharp features are
// covered: a vertex whose neighbourhood is not a known configuration is refined until it
// is, and its mask pulled back through the refinement's stencils, which is exact.
//
// A vertex the analysis can only approximate (no convergent mask, too many refinements)
// is refused with its number and the analysis's reason: an approximate operator would
// make the interpolation converge to the wrong surface.
#include <memory>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/interpolation/limit_evaluator.h"

namespace subdiv {

class AnalysedLimit final : public LimitEvaluator {
public:
  AnalysedLimit(std::shared_ptr<const Scheme> scheme, const FeatureOptions& features);
  std::string name() const override;

protected:
  StencilTable stencils_at(const Level& level, int step) const override;

private:
  std::shared_ptr<const Scheme> scheme_;
  std::shared_ptr<SchemeLimits> limits_;  // caches masks across levels and calls; thread-safe
  // A scheme without boundary or crease rules has limit masks on meshes that need none
  // (closed, no sharpness): the analysis' neighbourhoods then take stand-in rim rules
  // (analysis/surface/rim_rules.h), which never reach the masks. Null for other schemes.
  std::shared_ptr<const Scheme> rim_scheme_;
  std::shared_ptr<SchemeLimits> rim_limits_;
};

}  // namespace subdiv
