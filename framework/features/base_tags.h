#pragma once
// Tags a base level receives from its topology and the boundary option before refinement,
// in the order OpenSubdiv's factory applies them (Far::TopologyRefinerFactoryBase::
// prepareComponentTagsAndSharpness): holes first (they depend on the tags as given), then
// sharp non-manifold edges, then sharp boundary corners and non-manifold vertices. Being
// tags of the base level, they travel to finer levels with the others (features/sharpness.h).
#include "framework/features/feature_options.h"
#include "framework/topology/level.h"

namespace subdiv {

// BoundaryInterpolation::None: every face around a boundary vertex that has a boundary edge
// not tagged infinitely sharp becomes a hole, so the surface stops short of the boundary.
// Returns the number of faces made holes.
Index tag_boundary_holes(Level& base, BoundaryInterpolation mode);

// Non-manifold edges become infinitely sharp; so do non-manifold vertices, except on a
// non-manifold crease (two non-manifold edges, no boundary edge, more faces than edges),
// which then takes the crease rule along its two sharp edges.
void sharpen_non_manifold(Level& base);

// BoundaryInterpolation::EdgesAndCorners: a vertex with one face and two edges becomes an
// infinitely sharp corner, so the tag travels to finer levels even where a split gives the
// vertex more faces (sqrt3).
void tag_boundary_corners(Level& base, BoundaryInterpolation mode);

// All three, in that order: the tags refinement gives a base level before its first step.
void tag_base_level(Level& base, BoundaryInterpolation mode);

}  // namespace subdiv
