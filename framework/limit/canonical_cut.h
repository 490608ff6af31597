#pragma once
// A cut (a face's neighbourhood, analysis/surface/local_patch.h) renumbered by its canonical
// labelling, so that every cut with one signature is the same level and the engine's weights
// for it the same bits whichever cut was met first (the results do not depend on the order
// or thread of evaluations). Edge and vertex sharpness go with it; hole tags do not (holes
// remove faces, not rules). limit_nodes.cpp has its own, which keeps the holes too.
#include "framework/topology/level.h"

namespace subdiv {

struct Labelling;

// Faces in the order of their label lists (each from its smallest label), the centre `face`
// with its corner 0 first (its labels 0 .. n - 1), whose new index is `canonical_face`.
Level canonical_cut(const Level& cut, const Labelling& lab, Index face, Index& canonical_face);

// The cut's edge and vertex sharpness on `labelled`, its renumbering by `lab`.
void carry_sharpness(Level& labelled, const Level& cut, const Labelling& lab);

}  // namespace subdiv
