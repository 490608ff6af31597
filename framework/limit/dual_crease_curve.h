#pragma once
// The limit of an infinitely sharp crease at the middle of a crease edge, for a dual scheme
// whose crease rule moves the crease points after the split (even-degree quad B-splines of
// d >= 4: Chaikin's cuts, then Lane & Riesenfeld's averaging passes along the crease), so the
// middle of a crease edge is no longer the mean of its ends.
//
// The crease points' rows read crease points only, so the crease is refined by a curve scheme
// of its own, and the middle of crease edge (p, q) is the middle of the F-face's crease edge
// one step down (Greville: p, q at 0, 1; their new points at 1/4, 3/4). The crease points
// within m steps of the edge on either side, and their new points around the new edge, give
// the crease curve's local subdivision matrix S there; the limit at the middle is its left
// eigenvector of eigenvalue 1 (as the curve analysis takes a curve scheme's limit masks),
// with m grown until the new points read only the window. Empty where the window, or the
// `corner_reach` crease edges beyond it, reach a corner of the mesh or the end of the crease
// in `parent` (the curve there is not self-similar yet: the scheme's rules near a corner
// differ, and one more step moves the corner twice as far away).
#include <optional>
#include <utility>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/limit/dual_crease_chart.h"
#include "framework/scheme/scheme.h"

namespace subdiv {

// `h`: one step of the scheme from `parent` (levels[0]); `face`: a face of `parent` whose
// crease run is one infinitely sharp edge (run.length == 2). Weights on parent's vertices.
std::optional<std::vector<std::pair<Index, double>>> crease_middle_limit(const Level& parent, const Hierarchy& h,
                                                                         Index face, CreaseRun run, int corner_reach);

// How many crease edges from a corner a step of `scheme` uses other crease rules than along
// the rest of the crease (its "crease-ends" rules, by distance and by a short crease's length:
// CreaseEndTable::search_reach, over the step's passes); 0 without them.
int crease_end_reach(const Scheme& scheme);

}  // namespace subdiv
