#pragma once
// Where each child vertex of a refinement step came from.
#include <cstdint>
#include <optional>
#include <vector>

#include "framework/topology/level.h"
#include "framework/util/scratch_vector.h"

namespace subdiv {

enum class OriginKind : std::uint8_t { Vertex = 0, Edge = 1, Face = 2, Corner = 3 };

// Set by a split that lays out each kind's children as one run in element order (element
// i's only child is first[kind] + i; a kind with no children has count 0), so the rules
// need not scan the origins to group the children (rules/step_rows.cpp, group_children).
struct ChildRuns {
  Index first[4] = {kNone, kNone, kNone, kNone};
  Index count[4] = {};
};

// The per-child arrays are ScratchVectors (util/scratch_vector.h): the splits write every
// element of the arrays they size, in parallel, with no zero-fill before.
struct ChildOrigins {
  ScratchVector<OriginKind> kind;   // per child vertex
  ScratchVector<Index> parent;      // parent vertex, edge or face (for Corner: the face)
  ScratchVector<LocalIndex> local;  // Corner: corner index within the face; Edge: point along it; else 0
  ScratchVector<Index> parent_face;   // per child face: the parent face it lies in (kNone if none)
  std::optional<ChildRuns> runs;  // empty when the layout is another
  // Set only by the dual split of a level with features (refine/dual_crease_topology.h): per
  // child vertex, 1 for the point on the arriving edge of a corner with two sharp face edges,
  // else 0. Its presence tells the corner rule that glued and collapsed points exist.
  std::vector<std::uint8_t> corner_side;
};

}  // namespace subdiv
