#pragma once
// Two sqrt3 steps as one split of each triangle into nine (Kobbelt 2000, "sqrt(3)-Subdivision"):
// the first step puts a point at each face's centroid and flips the old edges, the second does
// it again (trisecting boundaries and creases, as the second of a pair does), and then the
// children of a triangle are the nine triangles of its triadic grid — corners, edge thirds and
// centroid (docs/limit.md, "√3 schemes"). A point of a sequence's head is carried through such
// a pair in one go (sequence_head.h).
#include <vector>

#include "framework/limit/face_domain.h"
#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

// For each face of `parent`, the faces of `grand` (two sqrt3 steps later, through `middle`)
// that tile it, each with its corners in the face's (u, v) (corners (0, 0), (1, 0), (0, 1)).
// A vertex of `grand` is placed by its origins: a vertex child where its parent is, a face
// point at its face's centroid (a face across an edge unfolded into the parent's plane), a
// trisection point at the third of its edge. Faces the steps do not split into nine (a pair
// whose first step trisects a feature, a collapsed face) get what was found; the caller checks.
std::vector<std::vector<ChildFace>> sqrt3_pair_children(const Level& parent, const Level& middle, const Level& grand,
                                                        const ChildOrigins& first, const ChildOrigins& second);

}  // namespace subdiv
