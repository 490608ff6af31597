#pragma once
// Elements no refiner can use, dropped before refinement with a count for a warning:
// faces with fewer than 3 distinct vertices (they enclose no area; a face that repeats a
// vertex but keeps 3 or more distinct ones, such as a quad pole, stays: OpenSubdiv refines
// it), and vertices that no face or polyline uses (OpenSubdiv ignores them too). Tags are
// renumbered; tags on dropped elements go with them.
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"

namespace subdiv {

struct MeshCleanup {
  Index dropped_faces = 0, dropped_vertices = 0;
  // One warning per kind of element dropped, naming how many; empty when nothing was.
  std::vector<std::string> warnings(const std::string& source) const;
};

// `mesh` without those elements; `report` says how many went.
MeshData drop_unrefinable(const MeshData& mesh, MeshCleanup& report);

}  // namespace subdiv
