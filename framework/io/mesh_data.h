#pragma once
// A mesh as read from or written to a file: positions, polygons, polylines and feature tags.
// This is the exchange type between io/ and the engine; it knows nothing of refinement.
#include <string>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

struct CreaseTag {
  Index v0, v1;
  double sharpness;
};
struct CornerTag {
  Index v;
  double sharpness;
};

struct MeshData {
  std::vector<double> positions;  // xyz per vertex
  std::vector<Index> face_offsets{0};
  std::vector<Index> face_vertices;
  std::vector<Index> line_offsets{0};  // polylines (OBJ 'l', VTK line cells)
  std::vector<Index> line_vertices;
  std::vector<CreaseTag> creases;  // OBJ 't crease', feature sidecar
  std::vector<CornerTag> corners;  // OBJ 't corner'

  Index vertex_count() const { return Index(positions.size() / 3); }
  Index face_count() const { return Index(face_offsets.size()) - 1; }
  Index line_count() const { return Index(line_offsets.size()) - 1; }
};

}  // namespace subdiv
