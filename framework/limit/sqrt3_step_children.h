#pragma once
// Where a point of a triangle goes in sqrt3 steps (Kobbelt 2000, "sqrt(3)-Subdivision"), for a
// sequence's head (sequence_head.h). A step puts a point at each face's centroid and flips the
// old edges, so a new triangle (a, P_f, P_g) straddles the edge a-b between faces f and g.
// Seen in f's (u, v) with g unfolded across the edge (its third corner at a + b - c, an
// affine map that g's frame sees the same way from its side), every new vertex has a place —
// a vertex child its parent's, a face point its face's centroid, a trisection point (in the
// steps that trisect boundaries and creases) the third of its edge — and every new triangle
// over f is affine in f's coordinates.
//
// Two steps whose first keeps the boundaries and creases make each triangle's triadic grid of
// nine, the layout sqrt3's own evaluator follows (sqrt3_limit.h): a pair is placed in the
// first face's frame, so that `sqrt3:2,B` has the parameters of sqrt3. One step alone is
// placed in the face's frame too; its triangles reach beyond the face, so its (u, v) is affine
// on the pieces they cut from the face (the tail's derivatives change across the cuts).
#include <vector>

#include "framework/limit/face_domain.h"
#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

// For each face f of `parent`, the faces of `child` (one sqrt3 step later) made from f or a
// face across one of its edges, with their corners in f's (u, v) (corners (0, 0), (1, 0),
// (0, 1)): together they cover f, and `locate` (face_domain.h) finds the one holding a point.
std::vector<std::vector<ChildFace>> sqrt3_step_children(const Level& parent, const Level& child,
                                                        const ChildOrigins& origins);

// For each face of `parent`, the faces of `grand` (two steps later, through `middle`) inside
// it, with their corners in its (u, v): the nine of its triadic grid when the first step keeps
// the features (the caller checks the count).
std::vector<std::vector<ChildFace>> sqrt3_pair_children(const Level& parent, const Level& middle, const Level& grand,
                                                        const ChildOrigins& first, const ChildOrigins& second);

}  // namespace subdiv
