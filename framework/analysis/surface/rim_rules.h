#pragma once
// The synthetic patch of an interior analysis is a finite piece of mesh: its outer rim is a
// boundary that refinement must give points to, though none of them reaches the invariant
// ring the analysis keeps (the analysis finds that ring by checking that its rows depend on
// nothing outside it). A scheme written without boundary rules can therefore still be
// analysed at interior vertices and faces: its rim takes stand-in rules.
#include <memory>

#include "framework/analysis/surface/local_patch.h"
#include "framework/scheme/scheme.h"

namespace subdiv {

// `scheme` itself when it has boundary rules or the configuration has a boundary, crease or
// corner of its own; otherwise a copy whose boundaries keep old points and put new ones at
// the middles of edges (any affine rule would do), held by `holder`.
const Scheme& scheme_for_patch_rim(const Scheme& scheme, const LocalConfig& config,
                                   std::shared_ptr<const Scheme>& holder);

}  // namespace subdiv
