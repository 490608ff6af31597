#pragma once
// Vertices that no face or polyline uses, dropped before refinement with a count for a
// warning (OpenSubdiv leaves them alone too: they have no neighbours and no children worth
// writing). Tags are renumbered; tags on dropped vertices go with them. Faces are all kept,
// those that repeat a vertex included, even with fewer than 3 distinct vertices ((a, a, b, b)):
// OpenSubdiv refines them, and so does the level builder (topology/level_builder.cpp).
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"

namespace subdiv {

struct MeshCleanup {
  Index dropped_vertices = 0;
  // One warning naming how many vertices were dropped; empty when none were.
  std::vector<std::string> warnings(const std::string& source) const;
};

// `mesh` without those vertices; `report` says how many went. The first form moves `mesh`
// through unchanged when nothing goes (a 1M-face mesh is tens of megabytes).
MeshData drop_unrefinable(MeshData&& mesh, MeshCleanup& report);
MeshData drop_unrefinable(const MeshData& mesh, MeshCleanup& report);

}  // namespace subdiv
