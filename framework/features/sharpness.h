#pragma once
// Sharpness one level down, scheme-independent (DeRose, Kass, Truong 1998; OpenSubdiv's
// Sdc::Crease): sharpness drops by one per level; infinitely sharp (>= 10) stays.
//
// Sharpness is single precision and every operation below is the one OpenSubdiv performs,
// in the same order, so that child sharpness values (and the fractional weights made from
// them) are bit for bit OpenSubdiv's.
#include <span>

#include "framework/features/feature_options.h"
#include "framework/topology/level.h"

namespace subdiv {

constexpr float kInfinitelySharp = 10.f;

inline bool is_semi_sharp(float s) { return s > 0.f && s < kInfinitelySharp; }

// Sharpness one level down (Sdc::Crease::decrementSharpness): s - 1 while s > 1, 0 from
// s <= 1; infinitely sharp stays.
float decremented_sharpness(float s);

// The child sharpness of every edge around one vertex, from the sharpness of all the
// vertex's edges (boundary edges counted as infinitely sharp): for each edge, the
// sharpness of its child half next to the vertex (Sdc::Crease::
// SubdivideEdgeSharpnessesAroundVertex). Uniform: decremented. Chaikin: a semi-sharp edge
// takes 3/4 of its own sharpness plus 1/4 of the mean of the vertex's other semi-sharp
// edges, minus one; with no other semi-sharp edge, it is decremented.
void subdivide_sharpness_around_vertex(std::span<const float> parent, std::span<float> child, CreaseMethod method);

// Sharpness of the child half, next to its end v, of parent edge e (Sdc::Crease::
// SubdivideEdgeSharpnessAtVertex). Boundary edges count as infinitely sharp.
float child_edge_sharpness(const Level& parent, Index e, Index v, CreaseMethod method);

}  // namespace subdiv
