#pragma once
// Face-varying channels through adaptive refinement (adaptive_refine.h): each channel's value
// mesh (AdaptiveValueMesh: the base's faces over the values, seams as boundaries) goes
// through a chain of stages of its own, refined with the scheme and the value mesh's tags as
// uniform face-varying refinement refines the whole value mesh (primvar/face_varying.h;
// OpenSubdiv's Vtr::FVarLevel). Each step refines the faces whose children the vertex stage
// keeps, with their ghost rings in the value mesh (a seam ends them), and keeps the same
// children: each vertex stage face's parent and place among its parent's children
// (AdaptiveStage::parent, rank) pick it. A value's ring of faces lies inside its vertex's, so
// the faces a vertex stage holds around the faces it refines hold the values' neighbourhoods.
//
// Stage l of a channel has the vertex stage l's faces in the same order with the same
// corners, so a face corner's value is the value vertex at the same corner of the same face.
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/limit/adaptive_refine.h"
#include "framework/limit/adaptive_stage.h"

namespace subdiv {

struct AdaptiveValueStage {
  Level level;                  // the value mesh's part: the vertex stage's faces, in order
  std::vector<double> values;   // AdaptiveValueMesh::components per value
  // Filled by refine_value_stage: this stage's values and value edges in the next stage
  // (kNone where not computed).
  std::vector<Index> vertex_child, edge_child;
};

// The channel at level 0. Throws subdiv::Error when its faces are not the base's.
AdaptiveValueStage value_base_stage(const Level& base, const AdaptiveValueMesh& channel);

// Refines `stage` as `vertex_stage` was refined (refine_stage) into `vertex_next`, whose
// faces' `parent` and `rank` say which children to keep; `options` as for the vertex stage
// (the boundary rule is made EdgesOnly: the value mesh's corners are tagged). Throws
// subdiv::Error when the value mesh's split does not give a face the vertex stage kept.
// With `last` (nothing refines the new stage further) the new stage's level has its faces
// only (no edges, rings or tags), all its faces and corners need.
AdaptiveValueStage refine_value_stage(const Scheme& scheme, const AdaptiveStage& vertex_stage,
                                      const AdaptiveStage& vertex_next, AdaptiveValueStage& stage,
                                      const AdaptiveValueMesh& channel, int ghost_rings, RefineOptions options,
                                      bool last = false);

}  // namespace subdiv
