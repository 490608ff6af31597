#pragma once
// Feature tags of a child level from its parent's, for the primal splits: the sharpness
// rules themselves are scheme-independent and live in features/sharpness.h.
#include "framework/features/sharpness.h"
#include "framework/refine/splitter.h"

namespace subdiv {

// Fills result.child.edge_sharpness / vertex_sharpness from the parent's tags, for splits
// whose child vertex of parent vertex v is v and whose child edges along parent edge e
// join v's child to e's child.
void propagate_tags(const Level& parent, SplitResult& result, CreaseMethod method);

}  // namespace subdiv
