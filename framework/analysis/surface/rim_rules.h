#pragma once
// A neighbourhood cut out of a mesh — the analysis' synthetic patch, or the piece of mesh a
// limit evaluation refines around a point — has an outer rim: a boundary that refinement
// must give points to, though none of them reaches the part that is kept (the analysis checks
// that the invariant ring's rows depend on nothing outside it; the limit evaluation cuts
// rings enough wider than the scheme's reach). A scheme written without boundary rules can
// therefore still be analysed at interior vertices and evaluated on a closed mesh without
// creases: its rims take stand-in rules.
#include <memory>

#include "framework/analysis/surface/local_patch.h"
#include "framework/scheme/scheme.h"

namespace subdiv {

// A copy of `scheme` whose boundaries keep old points and put new ones at even spacing along
// each edge (any affine rule would do; the split's curve arity: 3 for sqrt3, else 2).
std::shared_ptr<const Scheme> with_stand_in_rim_rules(const Scheme& scheme);

// Whether refinement needs no boundary or crease rule on the mesh: closed, manifold, without
// sharpness. A scheme without such rules refines it, and the neighbourhoods cut out of it
// may take with_stand_in_rim_rules.
bool needs_no_feature_rules(const Level& mesh);

// `scheme` itself when it has boundary rules or the configuration has a boundary, crease or
// corner of its own; otherwise with_stand_in_rim_rules(scheme), held by `holder`.
const Scheme& scheme_for_patch_rim(const Scheme& scheme, const LocalConfig& config,
                                   std::shared_ptr<const Scheme>& holder);
// The same for neighbourhoods cut out of a mesh: stand-ins where the mesh needs no feature rule.
const Scheme& scheme_for_cut_rims(const Scheme& scheme, const Level& mesh, std::shared_ptr<const Scheme>& holder);

}  // namespace subdiv
