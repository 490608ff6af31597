#pragma once
// The dual split (Doo & Sabin 1978) of a level with interior features: sharp edges cut the
// mesh into sides, each refined as a surface with a boundary, and the sides are glued along
// the crease points they share (docs/features.md, "Creases in dual schemes"):
//
// - a sharp edge e = (v, w) (features/dual_features.h) has no E-face; its two faces share
//   one child point near each end that does not collapse, the curve scheme's point on e
//   there, and the child edge between those two points is sharp (e's sharpness less one);
// - a collapsing vertex (a corner) gives one child point, shared by all its face corners,
//   which keeps its vertex sharpness less one;
// - a face corner whose two face edges are both sharp (a crease turning inside the face)
//   gives two points, one on each edge, so the F-face gains a corner;
// - the faces around a vertex between two consecutive sharp edges (a sector) make one face
//   of their corner points, as a boundary vertex's faces make its V-face; the edge closing it
//   joins the crease points of the two sharp edges and carries their mean sharpness less one.
//
// Child faces, in order: the F-faces (one per parent face), the E-faces of smooth edges,
// then the sector faces. Child vertices are numbered in order of the first parent corner
// that uses them; each origin is that corner, with `corner_side` 1 for the second point of
// a corner with two sharp edges.
#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

struct DualFeatureSplit {
  Level child;  // its edge sharpness decayed uniformly
  ChildOrigins origins;
  std::vector<float> averaged_edge_sharpness;  // under Chaikin's decay, where it differs (else empty)
};

// With `full`, the whole child level with its sharpness tags; otherwise its faces only.
// Non-manifold elements are handled locally: a non-manifold edge is sharp (its sides glue
// as a crease's do), a non-manifold vertex gets no sector face (counted in
// `skipped_vertices`), so one such vertex does not cost the rest of the level its creases.
DualFeatureSplit dual_feature_split(const Level& parent, bool full, Index* skipped_vertices = nullptr);


}  // namespace subdiv
