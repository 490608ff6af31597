#pragma once
// The sector of an edge's end that holds the edge, for the edge rules' sector roles and
// variables (docs/scheme-format.md, "Edge rules"). A feature vertex — one with two or more
// feature edges (boundary edges and edges of sharpness > 0) — splits its ring into sectors
// between consecutive feature edges: a boundary vertex has one, a crease vertex two (a crease
// is a boundary to each side, as Zorin 1998 treats it), a corner one per pair of consecutive
// feature edges. A sector of m faces has ring points p_0 .. p_m, CCW, p_0 and p_m across its
// two feature edges. A smooth edge (v, p_e) lies in exactly one sector of v, at 1 <= e <= m - 1.
#include "framework/features/feature_context.h"
#include "framework/rules/weight_tables.h"
#include "framework/topology/level.h"

namespace subdiv {

struct EndSector {
  int first = 0;  // ring position of p_0 (the ring edge to it)
  int faces = 0;  // m; 0 when the end is not a feature vertex or the edge is itself a feature
  int index = 0;  // e, the edge's place among p_0 .. p_m
};

// End `end` of edge e. None (faces = 0) at a vertex with fewer than two feature edges (a smooth
// vertex, a dart, a corner tagged by vertex sharpness alone), at a non-manifold vertex, and for
// a feature edge (which bounds sectors rather than lying in one).
EndSector end_sector(const Level& L, const FeatureContexts& F, Index e, Index end);

// The sizes m of the level's sectors, ascending (a superset: a boundary vertex also counts the
// gap across its boundary as a sector of one face), for the weight tables
// (LevelValences::sector_sizes). Feature edges as classify_features finds them: boundary edges
// and edges tagged with sharpness > 0.
std::vector<int> sector_sizes_present(const Level& L);

// The sector variables of edge e = (a, b) (weight_tables.h).
SectorVariables sector_variables(const EndSector& at_a, const EndSector& at_b);

}  // namespace subdiv
