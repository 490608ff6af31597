#pragma once
// How many rings of ghost faces a piece needs (engine/mesh_pieces.h) so that its own faces
// refine exactly as in the whole mesh: read off the schemes' rules, never their names.
//
// A child point of a step depends on the parent points its rule reads, and on the parent
// topology its rule and the split look at. Measured in rings of the parent level from where
// the child lies (its element's vertex, or the middle of its edge or face), that is the
// step's reach R: 1 for a vertex rule over the vertex's ring or faces, 1/2 for a rule over
// an edge's or a face's own vertices, 3/2 for rules over an edge's far wings or its ends' rings, and along creases the
// curve scheme's support (table in docs/scale.md). A piece whose points are right up to m
// parent rings beyond its faces has right child points up to m - (R - 1/2) parent rings
// beyond them (children lie on the half rings), which is s (m - R + 1/2) rings of the child
// level, s the split's ring scale (SplitterInfo::ring_scale); a smoothing pass of reach R takes R rings of its own level.
// Starting from the ghost rings g, the last level must still be right on the piece:
// g >= sum over levels l of rho_l / (s_0 ... s_{l-1}), rho_l the level's loss in its parent's
// rings, and the smallest such whole g is the width.
#include <span>
#include <vector>

#include "framework/scheme/scheme_run.h"

namespace subdiv {

// Per level of the runs (in order), the rings of its parent level that the level loses:
// the split's reach less 1/2, plus its smoothing passes' reach over the split's scale.
// Throws subdiv::Error for a scheme whose reach cannot be read: rules written in C++
// (plugins), roles or splits registered by a plugin that do not state their reach.
std::vector<double> ring_loss_per_level(std::span<const SchemeRun> runs);

// The smallest number of ghost rings for the runs' levels (see above); 0 when every child
// reads nothing beyond its own parent face (vertices that stay, means of an edge or a face).
int ghost_rings(std::span<const SchemeRun> runs);

}  // namespace subdiv
