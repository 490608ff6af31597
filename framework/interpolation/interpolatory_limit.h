#pragma once
// Interpolatory schemes (their vertex points are the old vertices): every control vertex is
// its own limit point. Whether a scheme is one is decided by limit_selection.h's l S = l
// test on the mesh, not by its name.
#include "framework/interpolation/limit_evaluator.h"

namespace subdiv {

class InterpolatoryLimit final : public LimitEvaluator {
public:
  std::string name() const override { return "interpolatory (vertices stay)"; }

protected:
  StencilTable stencils_at(const Level& level, int step) const override;
};

}  // namespace subdiv
