#pragma once
// Mesh lines for plugin rules on quad meshes: the straight lines of a regular grid,
// continued through regular vertices and along boundaries and creases. Rules such as
// four-point schemes on quad meshes (Kobbelt 1996) walk them.
#include "framework/features/feature_context.h"
#include "framework/topology/level.h"

namespace subdiv {

// The edge that continues the line of edge `e` beyond its end `end`, or kNone where the
// line stops. A smooth edge continues straight through a regular interior vertex (valence
// 4, no sharp edges): the ring edge opposite e. A feature edge (boundary or sharp)
// continues along the other feature edge of a crease vertex. Lines stop at extraordinary
// vertices, corners and darts.
Index edge_beyond(const Level& level, const FeatureContexts& features, Index e, Index end);

// The vertex one step beyond `end` on the line of edge e, or kNone.
Index vertex_beyond(const Level& level, const FeatureContexts& features, Index e, Index end);

// For quad f and its edge e: the edge parallel to e one face further out (the edge
// opposite e in the quad across e), or kNone when e is a boundary or sharp edge or the
// face across is not a quad.
Index parallel_edge_across(const Level& level, const FeatureContexts& features, Index f, Index e);

// The edge of quad f opposite its edge e.
Index opposite_edge_in_quad(const Level& level, Index f, Index e);

}  // namespace subdiv
