#pragma once
// Child topology of the sqrt3 split (sqrt3_split.cpp) built from the parent's arrays, for the
// common case where every edge is flipped: a closed manifold triangle mesh without sharp
// edges (nothing is kept or trisected, so both step parities give the same child), every
// vertex with three faces or more. Other parents go through sqrt3_split.cpp's builder.
//
// Child vertices: the parent's, then face point V+f of face f. Child faces: 2e and 2e+1 for
// parent edge e = a -> b (f0 left, f1 right): (a, P(f1), P(f0)) and (b, P(f0), P(f1)), as
// sqrt3_split.cpp lists them. The full level is numbered as build_level numbers the same
// polygons, so the two ways give the same level (the tests compare every array).
#include "framework/topology/level.h"

namespace subdiv {

// Whether the parent takes the direct way.
bool sqrt3_flips_every_edge(const Level& parent);

// With `full`, the whole child level; otherwise its faces only. *parent_face: per child
// face, the parent face it lies in.
Level sqrt3_flip_topology(const Level& parent, bool full, ScratchVector<Index>* parent_face);

}  // namespace subdiv
