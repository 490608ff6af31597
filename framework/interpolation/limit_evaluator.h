#pragma once
// Limit points as a linear operator: the point of the limit surface that belongs to each
// control vertex, as a weighted sum of control points (a "limit mask" per vertex).
//
// Progressive interpolation (progressive.h) only needs this operator. The evaluators here
// are closed forms (closed_form_limits.h, shape_two_step.h) and dual schemes' V-face
// centroids (dual_limits.h); issue 6's masks from the eigen-analysis of any scheme plug in
// through limit_selection.h's provider hook (register_limit_mask_provider). Refining
// a few levels and taking the points as "nearly converged" is deliberately not offered:
// an approximate limit would make the interpolation converge to the wrong surface.
#include <span>
#include <string>

#include "framework/stencil/stencil_table.h"
#include "framework/topology/level.h"

namespace subdiv {

class LimitEvaluator {
public:
  virtual ~LimitEvaluator() = default;

  // A short name for messages, e.g. "Catmull-Clark closed form (seed 000)".
  virtual std::string name() const = 0;

  // Row v is the limit point of vertex v over the level's vertices (source_count =
  // rows = vertex_count). Throws subdiv::Error naming the first vertex the evaluator
  // cannot handle (a dart, a semi-sharp crease, a polygon the formula does not cover).
  virtual StencilTable limit_stencils(const Level& level) const = 0;

  // out[v * channels + c] = limit of control values (channels per vertex) at vertex v.
  void limit_points(const Level& level, std::span<const double> control, std::span<double> out,
                    int channels = 3) const {
    limit_stencils(level).apply(control, out, channels);
  }
};

}  // namespace subdiv
