#pragma once
// The limit surface of a linear scheme on a plugin's primal split (SplitterInfo::primal), at
// (face, u, v): splits whose children nest in their parent face after `period` steps, such
// as the √2 / 4-8 split (Li, Ma & Bao 2004; Velho & Zorin 2001), which turns a quad grid by
// 45 degrees each step and is a binary quad split every second step.
//
// Parameterisation: Bfr's quad (corners (0,0), (1,0), (1,1), (0,1)) or triangle ((0,0),
// (1,0), (0,1)) of each base face — the mesh must be all quads or all triangles — and the
// children placed by where the split says they come from, as for the built-in splits: a
// vertex child at its parent vertex, an edge child along its parent edge, a face child at
// the centroid of its parent face's corners; for `period` 2 the first step's points of the
// neighbouring faces are placed with the grid unfolded affinely across the shared edge. The
// split is taken when, after `period` steps, its faces inside a base face are m x m affine
// copies of it (m = scale^period, 2 or 3) that tile it; otherwise it is refused, naming why.
//
// Evaluation follows the point down `period` steps at a time, refining a cut around its face
// with the engine, until it is a vertex (a dyadic point under m = 2) or its face is below
// round-off (m^-k < 2^-53; for m = 3, 34 steps past the last face touching an extraordinary
// vertex, as for √3), and takes the vertex's limit and tangent masks there (corner_limit.h).
// Each step refines the cut with the engine (no node cache), so a point costs milliseconds.
#include <memory>
#include <string>
#include <vector>

#include "framework/limit/face_domain.h"
#include "framework/limit/limit_surface.h"
#include "framework/limit/step_matrix.h"

namespace subdiv {

class SchemeLimits;
class WeightTableCache;

class PluginSplitLimit {
public:
  PluginSplitLimit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options, SchemeLimits& limits);
  ~PluginSplitLimit();

  bool triangles() const { return triangles_; }
  std::vector<Index> reads(const FacePoint& p) const;

  using Rows = FirstDerivativeRows;  // step_matrix.h
  LimitSample evaluate(const FacePoint& p, const std::vector<double>& first_values, int channels, int derivatives,
                       Rows* rows_out = nullptr) const;

private:
  const Scheme& scheme_;
  const Level& base_;
  LimitSurfaceOptions options_;
  SchemeLimits& limits_;
  std::unique_ptr<WeightTableCache> tables_;  // cut_weight_tables.h
  bool triangles_ = false;
  int period_ = 1, factor_ = 2, radius_ = 5;
};

// Why the plugin-split evaluation cannot take this scheme and mesh, or empty.
std::string plugin_split_limit_unsupported(const Scheme& scheme, const Level& base);

}  // namespace subdiv
