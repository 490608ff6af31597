#pragma once
// The head of a scheme sequence ("A:1,B:3") before the scheme that repeats: the limit of
// the sequence is the limit of its last scheme over the mesh the head makes, so a base
// point (face, u, v) is carried through the head's splits into a face of that mesh (each
// child face holds a part of its parent, face_domain.h), and weights over that mesh's
// vertices are pulled back through the head's stencils to the base vertices.
//
// The head only refines, a finite number of levels, so any linear rules will do there —
// level-dependent (non-stationary) weights included; only the repeating tail needs a fixed
// local subdivision matrix. Its splits must nest: binary quad or triangle splits, the dual
// split through its quadrants (dual_limit.h) on a closed untagged mesh, mid-edge steps in
// pairs, which nest as a dual step (mid_edge_pair.h), on a closed mesh without creases, or
// sqrt3 steps, whose new triangles are affine in the (u, v) of the faces they reach over
// (sqrt3_step_children.h), or a plugin's primal split a period at a time on the meshes its
// own evaluation takes (plugin_period_children.h, plugin_split_limit.h).
#include <memory>
#include <string>
#include <vector>

#include "framework/analysis/surface/sparse_rows.h"
#include "framework/engine/refiner.h"
#include "framework/limit/face_domain.h"
#include "framework/limit/limit_surface.h"

namespace subdiv {

struct Scheme;

class SequenceHead {
public:
  // Throws subdiv::Error saying why a head cannot be followed (a split that does not nest,
  // non-linear rules).
  SequenceHead(std::vector<LimitHeadRun> runs, const Level& base, const FeatureOptions& features);

  const Level& refined() const { return hierarchy_.levels.back(); }
  // True when the first split makes triangles: the base faces are then parameterised as triangles.
  bool triangles() const { return triangles_.front() != 0; }
  int levels() const { return int(hierarchy_.origins.size()); }

  // The base point in the refined mesh: its face, the face's own (u, v) in `st`, and
  // d(st)/d(u, v) in `jacobian`. Throws subdiv::Error for a point outside the base face.
  FacePoint map(const Level& base, Index face, double u, double v) const;
  // Weights over the refined mesh's vertices as weights over the base vertices.
  SparseRow pull_back(SparseRow row) const;

private:
  void place_sqrt3_children();
  void pair_mid_edge_steps();
  void place_plugin_children();

  std::vector<LimitHeadRun> runs_;
  Hierarchy hierarchy_;
  std::vector<char> triangles_;  // per level: its split makes triangles
  std::vector<char> dual_;       // per level: its split is the dual one (dual_limit.h)
  std::vector<char> sqrt3_;      // per level: its split is sqrt3
  // Per sqrt3 level: each face's children one level down, or two for the first of a pair
  // (sqrt3_pair_ set; sqrt3_step_children.h).
  std::vector<std::vector<std::vector<ChildFace>>> sqrt3_children_;
  std::vector<char> sqrt3_pair_;
  std::vector<char> mid_edge_;  // per level: its split is mid-edge (followed in pairs)
  // Per level starting a pair of mid-edge steps: the grand level's origins as a dual split's.
  std::vector<ChildOrigins> mid_edge_origins_;
  std::vector<char> plugin_;  // per level: its split is a plugin's (followed a period at a time)
  // Per level starting a plugin split's period: the period, and each face's children a period
  // down (0 and empty at the period's other levels).
  std::vector<int> plugin_period_;
  std::vector<std::vector<std::vector<ChildFace>>> plugin_children_;
};

// Why a scheme cannot be a sequence's head, or empty.
std::string sequence_head_unsupported(const Scheme& scheme);

}  // namespace subdiv
