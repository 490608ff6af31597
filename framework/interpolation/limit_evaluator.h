#pragma once
// Limit points as a linear operator: the point of the limit surface that belongs to each
// control vertex, as a weighted sum of control points (a "limit mask" per vertex).
//
// Progressive interpolation (progressive.h) only needs this operator. The evaluators are
// the masks of the scheme's own eigen-analysis (analysed_limit.h, any linear scheme with
// vertex points), dual schemes' V-face centroids (dual_limits.h), interpolatory schemes'
// identity (interpolatory_limit.h), the composite of a sequence (limit_selection.h), and any a
// plugin registers (limit_selection.h). Refining a few levels and taking the points as
// "nearly converged" is deliberately not offered: an approximate limit would make the
// interpolation converge to the wrong surface.
#include <span>
#include <string>

#include "framework/stencil/stencil_table.h"
#include "framework/topology/level.h"

namespace subdiv {

class LimitEvaluator {
public:
  virtual ~LimitEvaluator() = default;

  // A short name for messages, e.g. "limit masks of catmull-clark's eigen-analysis".
  virtual std::string name() const = 0;

  // Row v is the limit point of vertex v over the level's vertices (source_count =
  // rows = vertex_count). `step` is how many refinement steps made the level from the
  // input mesh (RefineOptions::first_step), for schemes whose rules alternate or depend on
  // the level. Throws subdiv::Error naming the first vertex without an exact limit mask.
  StencilTable limit_stencils(const Level& level, int step = 0) const { return stencils_at(level, step); }

  // out[v * channels + c] = limit of control values (channels per vertex) at vertex v.
  void limit_points(const Level& level, std::span<const double> control, std::span<double> out, int channels = 3,
                    int step = 0) const {
    limit_stencils(level, step).apply(control, out, channels);
  }

protected:
  virtual StencilTable stencils_at(const Level& level, int step) const = 0;
};

}  // namespace subdiv
