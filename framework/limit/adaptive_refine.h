#pragma once
// Feature-adaptive refinement (a first step towards OpenSubdiv's RefineAdaptive, Nießner,
// Loop, Meyer & DeRose 2012, "Feature-adaptive GPU rendering of Catmull-Clark subdivision
// surfaces"): only the faces that touch what is irregular — an extraordinary vertex, a
// crease, a sharp or semi-sharp vertex, a face of another shape than the split makes — are
// refined, level after level up to L; regular regions stay coarse.
//
// The mesh is watertight: a coarse face next to finer ones takes the finer vertices along
// its edges as corners of its own (a transition polygon), so no edge ends in the middle of
// another (no T-junction) and every interior edge has exactly two faces. Each vertex is
// placed where the uniform level L puts it (or on the limit surface, with `limit`), so the
// faces of different levels meet without cracks.
//
// First step: the positions come from a uniform refinement to level L (the output is
// adaptive, the work is not yet); no flatness or curvature criterion (--tolerance); the
// transition faces are polygons, not OpenSubdiv's triangulated transition patterns.
#include <memory>
#include <span>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/topology/level.h"

namespace subdiv {

struct Scheme;

struct AdaptiveMesh {
  std::vector<double> positions;            // xyz per vertex
  std::vector<Index> face_offsets{0}, face_vertices;
  std::vector<int> face_level;              // per face: the level it comes from
  std::vector<Index> base_face;             // per face: the base face it lies in
  Index uniform_faces = 0;                  // faces of the uniform level L, for comparison
};

// Throws subdiv::Error for a split other than the binary quad and triangle splits, and for
// levels outside 0..12.
AdaptiveMesh refine_adaptive(const Scheme& scheme, const Level& base, std::span<const double> positions, int levels,
                             const FeatureOptions& features, bool limit);

}  // namespace subdiv
