#pragma once
// A non-manifold base mesh as manifold sheets, for the limit evaluation.
//
// The rules make every non-manifold element a feature (features/base_tags.h, as
// OpenSubdiv's Far): a non-manifold edge is infinitely sharp, a non-manifold vertex a corner
// unless it lies on a non-manifold crease. A sharp edge's new points are the midpoints of
// its own halves and a corner stays, so no rule reads across them: each manifold fan of
// faces refines as if the others were not there. The sheets are those fans cut apart along
// the non-manifold edges and vertices (each fan its own copy of a vertex, each face its own
// copy of a non-manifold edge, which becomes a boundary edge): same faces, same face numbers,
// the tags the base level takes before refinement copied onto the copies, so the limit of a
// face in its sheet is its limit in the mesh. The boundary rules then make the same points:
// a non-manifold crease vertex is a boundary vertex of its sheet with the crease's two edges
// as its boundary edges; corners of the mesh's own boundary are tagged, so the sheets are
// evaluated with the boundary mode `Edges` (a sheet's one-face vertex on a cut is no corner).
#include <string>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/topology/level.h"

namespace subdiv {

struct ManifoldSheets {
  Level level;                // the sheets; face f is the base level's face f
  std::vector<Index> origin;  // per sheet vertex, the base vertex it copies
};

// The sheets of a non-manifold `base` under `features`. Throws subdiv::Error where the cut
// cannot make the mesh manifold (a face repeating a vertex, an edge from a vertex to itself)
// or where the crease method would read sharpness across a cut (Chaikin's rule at a vertex
// where a semi-sharp edge meets a cut).
ManifoldSheets manifold_sheets(const Level& base, const FeatureOptions& features);

}  // namespace subdiv
