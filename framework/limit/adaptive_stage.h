#pragma once
// One level of local refinement (adaptive_refine.h): a stage is the part of the uniform level
// l that was computed, exactly — its faces, their points, and per vertex whether every face
// the vertex has in the whole level is there (`complete`; elsewhere the stage's edge is an
// artificial cut, not a boundary). refine_stage splits the stage's faces marked `split` and
// the `rings` rings of faces around them, each with the scheme's ghost rings
// (engine/ghost_rings.h) read from the stage, so that every child face kept is the uniform
// level l + 1's face with its points, as in engine/mesh_pieces.h's refinement in pieces.
//
// Why the rings suffice (binary splits, ring scale 2): the faces to split at level l + 1 are
// children of those split at level l (their features, and faces out of tolerance, are
// inherited), and children of r rings of level l cover 2 r rings of level l + 1; with
// r >= g, the scheme's ghost rings, the next stage holds the next faces to split with their
// r rings and g ghost rings. refine_stage checks it and throws when a cut would be read.
#include <array>
#include <span>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/topology/level.h"

namespace subdiv {

struct Scheme;

struct AdaptiveStage {
  Level level;                      // faces of the uniform level, with its tags
  std::vector<double> points;       // `channels` per vertex: xyz, then the carried point arrays
  int channels = 3;
  std::vector<char> complete;       // per vertex
  std::vector<Index> base_face;     // per face
  std::vector<std::array<double, 2>> corner_uv;  // per corner: (u, v) in the base face
  std::vector<char> candidate;      // per face: may be split (its parent was)
  std::vector<char> split;          // per face: split for the output (set by the caller)
  // Per face (stages after the base): its parent face in the previous stage, and its place
  // among all the parent's children in the split (a stage may keep only some of them).
  std::vector<Index> parent;
  std::vector<int> rank;
  // Filled by refine_stage: this stage's vertices, edges and faces in the next stage.
  std::vector<Index> vertex_child, edge_child;  // kNone where not computed
  std::vector<std::vector<Index>> children;     // per face: its child faces
};

// The base mesh as stage 0 (every vertex complete, every face a candidate).
AdaptiveStage base_stage(const Level& base, std::span<const double> points, int channels, bool triangles);

// Refines `stage` (its `split` faces set) one level: see above. `options` gives the
// features and first_step (the stage's level counted from the original mesh). With `last`
// (nothing refines the new stage further) the new stage's level has its faces only
// (mesh_pieces.h: no edges, rings or tags), all its faces and corners need.
AdaptiveStage refine_stage(const Scheme& scheme, AdaptiveStage& stage, int rings, int ghost_rings,
                           const RefineOptions& options, bool triangles, bool last = false);

}  // namespace subdiv
