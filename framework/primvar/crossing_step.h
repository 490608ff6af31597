#pragma once
// One step of face-varying data through a split whose new faces may cross old edges: the
// flipped triangles of the sqrt3 split (each joins the face points of an old edge's two
// faces) and the vertex faces of the mid-edge split (each joins the midpoints of the edges
// around an old vertex). On a seam such a face joins two UV islands, so neither the
// island-by-island refinement of the quad and triangle splits nor the one-value-per-corner
// rule of the dual splits applies (docs/primvars.md, "Which splits").
//
// The rule (the natural equivalent): the data follows the vertex mesh's new topology, and
// every corner of a new face takes its value in ONE old face, so in one island:
//  1. the new face's parent face, when it holds the corner's point;
//  2. else the old face that holds both this corner's point and the preceding corner's (the
//     face the new face's incoming edge runs in; where that edge runs along an old edge,
//     the face on the new face's side of it, the one that runs it the same way);
//  3. else the same with the following corner (an edge that crosses an old edge, like the
//     edge a mid-edge vertex face closes over a boundary vertex).
// Around an old vertex this gives each of its corner values to exactly one new face of
// the sqrt3 split (the flipped triangle of each old edge takes the face left of the edge,
// which is also the triangle's parent face) and of a mid-edge vertex face (each midpoint
// takes the face between it and the previous midpoint), so every island keeps its share
// and the choice depends on orientation only, never on numbering.
//
// The corner's value is then the scheme's rule for its point applied in that face's
// island: the value mesh (the vertex mesh's faces over the value indices, seams as
// boundaries) gives the rows, with the origins of the vertex mesh's new points moved onto
// it — an old vertex becomes the value it has in that face, an edge point the point of the
// value edge with the same place along it, a face point stays. So where the value mesh
// agrees with the vertex mesh (no seam near) the data is refined exactly as positions are;
// at seam values the island's boundary rule, or the corner rule the linear-interpolation
// mode chose, applies.
#include <span>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/primvar/face_varying.h"

namespace subdiv {

// True when every corner of every new face lies in the face's parent face (the quad and
// triangle splits): then the islands can be refined one by one with the split itself.
bool corners_in_parent_faces(const Level& parent, const ChildOrigins& origins, const Level& child);

struct CrossingStep {
  FaceVaryingLevel level;      // the new values and their index per new face corner
  Level values;                // the new value mesh (no tags yet)
  std::vector<Index> vertex_of;  // per new value: its vertex of `child`
  std::vector<Index> value_of_vertex_origin;  // per new value: the parent value it moved, or kNone
};

// `vertices` is the parent vertex level, `values` its value mesh (with the mode's tags),
// `origins` and `child` the vertex split's result, `features_refined` whether the step
// refined boundaries and creases. `options` are the step's (vertex parameters on values).
CrossingStep crossing_step(const SchemeRun& run, const Level& vertices, Level values, const ChildOrigins& origins,
                           const Level& child, bool features_refined, std::span<const double> parent_values,
                           int components, const RefineOptions& options);

}  // namespace subdiv
