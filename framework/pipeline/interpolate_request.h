#pragma once
// Progressive interpolation as every front-end asks for it (`subdiv interpolate`, Python's
// subdivkit.interpolate): the limit operator of the mesh under the scheme — curve limit
// stencils for polylines, the checked limit masks (limit_selection.h) for surfaces — then the
// iteration that moves the chosen control points until the limit passes through the targets
// (Chen et al. 2008; local form: Zhao, Lin, Bao 2012; framework/interpolation/progressive.h),
// and where the fixed points' limit points end (theorem 2 of Lin et al. 2015, "Local
// progressive interpolation for subdivision with shape control"). Writing the result is the
// front-ends' part.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "framework/curve/curve_level.h"
#include "framework/interpolation/limit_selection.h"
#include "framework/interpolation/progressive.h"
#include "framework/io/mesh_data.h"
#include "framework/pipeline/refine_request.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_sequence.h"
#include "framework/stencil/stencil_table.h"
#include "framework/topology/level.h"

namespace subdiv {

struct InterpolateRequest {
  MeshData mesh;          // polylines (with a curve scheme) or a surface; positions are the targets
  std::string mesh_name;  // names the mesh in messages
  SchemeSource scheme;    // a curve scheme, a surface scheme or a sequence "A:1,B"
  int levels = 1;         // completes a sequence, as refine's levels
  std::vector<std::uint8_t> moving;  // one flag per vertex (nonzero: moves); empty: all move
  double tolerance = -1;             // < 0: 1e-10 times the bounding-box diagonal of the targets
  int max_iterations = 1000;
  BoundaryInterpolation boundary = BoundaryInterpolation::EdgesAndCorners;
  int start_level = 0;
  VertexParameters vertex_parameters;  // per-vertex scheme parameters (Lin et al. 2015's lambda)
  std::function<void(const std::string& phase)> progress;
  std::function<void(const IterationRecord& record)> iteration;  // after each iteration
};

// The limit operator: control points to limit points, one row per vertex.
struct LimitOperator {
  StencilTable table;
  std::string description;  // the mask used and how it was checked (or the curve's weights)
};

struct InterpolateResult {
  ProgressiveResult iteration;  // control points, their limit points, residuals per iteration
  double tolerance = 0;         // the one used
  Index moving = 0, vertices = 0;
  std::string limit_description;
  std::string fixed_note;  // with fixed vertices: where their limit points end (theorem 2)

  // What a front-end needs to refine the result for display.
  std::shared_ptr<const CurveScheme> curve;  // set for polylines
  CurveLevel curve_base;
  SchemeSequence sequence;  // set for surfaces
  Level base;
  LimitSelectionOptions options;
};

// Throws subdiv::Error naming the mesh or the scheme, or OptionError naming an option.
InterpolateResult interpolate_mesh(InterpolateRequest request);

// The limit operator alone (limit positions of a mesh's vertices by stencils).
LimitOperator limit_operator(const InterpolateRequest& request);

}  // namespace subdiv
