#pragma once
// Where each child vertex of a refinement step came from.
#include <cstdint>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

enum class OriginKind : std::uint8_t { Vertex = 0, Edge = 1, Face = 2, Corner = 3 };

struct ChildOrigins {
  std::vector<OriginKind> kind;   // per child vertex
  std::vector<Index> parent;      // parent vertex, edge or face (for Corner: the face)
  std::vector<std::uint8_t> local;  // Corner: corner index within the face; else 0
  std::vector<Index> parent_face;   // per child face: the parent face it lies in (kNone if none)
};

}  // namespace subdiv
