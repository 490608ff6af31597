#pragma once
// One level of polylines and closed polygons for curve refinement, as flat arrays.
//
// Files: an OBJ 'l' line or a VTK line cell is a polyline; one whose last vertex repeats
// its first (OBJ "l 1 2 3 4 1") is a closed polygon. A CurveLevel lists a closed polygon's
// points once; mesh_from_curve_level writes the first index again at the end, so closed
// polygons survive a round trip through OBJ and .vtp.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/topology/level.h"

namespace subdiv {

struct CurveLevel {
  Index vertex_count = 0;
  std::vector<Index> offsets{0};     // CSR over vertices, one entry per polyline
  std::vector<Index> vertices;
  std::vector<std::uint8_t> closed;  // 1: closed polygon

  Index polyline_count() const { return Index(offsets.size()) - 1; }
  int size(Index p) const { return offsets[p + 1] - offsets[p]; }
  bool is_closed(Index p) const { return closed[p] != 0; }
  std::span<const Index> polyline(Index p) const {
    return {vertices.data() + offsets[p], size_t(size(p))};
  }
};

// The mesh's polylines. Throws subdiv::Error, naming `source`, when the mesh has faces (a
// curve scheme refines polylines only), has no polyline, or has a closed polygon of fewer
// than 3 points. The level keeps all the mesh's vertices, used by a polyline or not.
CurveLevel curve_level_from_mesh(const MeshData& mesh, const std::string& source);

// Positions (xyz per vertex) and polylines for writing; closed polygons repeat their first
// vertex at the end.
MeshData mesh_from_curve_level(const CurveLevel& level, std::vector<double> positions);

}  // namespace subdiv
