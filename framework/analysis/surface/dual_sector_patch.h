#pragma once
// The neighbourhood a dual scheme (Doo-Sabin, mid-edge, even-degree quad B-splines) has
// next to a boundary or crease vertex. A dual step turns a vertex into its V-face; next to
// a boundary, or where sharp edges cut the vertex's faces into sectors, each sector becomes
// one face with an edge on the boundary or crease (features.md, "Creases in dual schemes").
// That face is the structure the scheme reproduces level after level, so it is the centre
// of the analysis, as the V-face (an n-gon) is in the interior.
#include "framework/analysis/surface/local_patch.h"
#include "framework/features/feature_context.h"

namespace subdiv {

struct Scheme;

// The primal quad patch of the configuration (boundary, sharp rays, corner tag), refined
// by the scheme's own split and rules until the neighbourhood of the centre within `rings`
// - 1 (the rings the analysis labels) repeats from level to level, each level cut to the
// faces around the centre that the next one needs; the centre is the descendant of the face
// made for the vertex's first sector (the faces from ring edge 0 to the next sharp edge, or
// to the boundary): the sector's V-face, or for a sector of two faces the E-face of the edge
// between them. Throws when the configuration leaves no such face (a corner, whose points
// collapse into one; a sector of one face, whose F-face holds both crease points).
Patch make_dual_sector_patch(const Scheme& scheme, const LocalConfig& config, int rings, const FeatureOptions& features);

// The number of faces in the first sector of the configuration.
int first_sector_faces(const LocalConfig& config);

}  // namespace subdiv
