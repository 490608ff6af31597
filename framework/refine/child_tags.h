#pragma once
// Feature tags of a child level from its parent's (DeRose, Kass, Truong 1998; OpenSubdiv's
// Sdc::Crease): sharpness drops by one per level; infinitely sharp (>= 10) stays.
#include "framework/refine/splitter.h"

namespace subdiv {

// OpenSubdiv's Sdc::Options::CreasingMethod.
enum class CreaseMethod { Uniform, Chaikin };

constexpr float kInfinitelySharp = 10.f;

// Fills result.child.edge_sharpness / vertex_sharpness from the parent's tags, for splits
// whose child vertex of parent vertex v is v and whose child edges along parent edge e
// join v's child to e's child.
void propagate_tags(const Level& parent, SplitResult& result, CreaseMethod method);

// Sharpness one level down: s - 1, floored at 0; infinitely sharp stays.
float decremented_sharpness(float s);
// Sharpness of the child half of parent edge e next to its end v, with the given method.
float child_edge_sharpness(const Level& parent, Index e, Index v, CreaseMethod method);

}  // namespace subdiv
