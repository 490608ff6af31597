#pragma once
// Automatic feature detection (`subdiv refine --feature-angle DEG`): an edge whose dihedral
// angle, the angle between the normals of its two faces, exceeds a threshold becomes an
// infinitely sharp crease. A flat pair of faces has angle 0, the faces at a cube's edge 90,
// a fold back onto itself 180.
#include <span>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

// The angle in degrees between the normals of the two faces of interior edge e, or a
// negative value for a boundary edge or an edge next to a face of zero area. Polygon
// normals by Newell's method, so non-planar polygons get their average plane's normal.
double dihedral_angle_degrees(const Level& level, std::span<const double> xyz, Index e);

// The interior edges whose dihedral angle exceeds `degrees`, in edge order. Throws
// subdiv::Error unless 0 <= degrees <= 180.
std::vector<Index> edges_sharper_than(const Level& level, std::span<const double> xyz, double degrees);

// Makes those edges infinitely sharp (a sharper existing tag is never lowered) and returns
// how many edges were found.
Index tag_edges_sharper_than(Level& level, std::span<const double> xyz, double degrees);

}  // namespace subdiv
