#pragma once
// A mesh as read from or written to a file: positions, polygons, polylines and feature tags.
// This is the exchange type between io/ and the engine; it knows nothing of refinement.
#include <optional>
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

// Options of the refinement that a file states (OpenSubdiv's OBJ tags); unset when it does
// not. The command line wins over them.
struct MeshOptions {
  std::optional<int> interpolate_boundary;      // t interpolateboundary: 0 none, 1 edges and corners, 2 edges
  std::optional<std::string> crease_method;     // t creasemethod: "normal" (uniform) or "chaikin"
  std::optional<std::string> smooth_triangles;  // t smoothtriangles: "catmark" or "smooth"
  std::optional<int> fvar_interpolate_boundary;  // t facevaryinginterpolateboundary: 0..5 (Sdc::Options::FVarLinearInterpolation)
  std::optional<int> fvar_propagate_corners;     // t facevaryingpropagatecorners: 0 or 1
  bool any() const {
    return interpolate_boundary || crease_method || smooth_triangles || fvar_interpolate_boundary || fvar_propagate_corners;
  }
};

struct MeshData {
  std::vector<double> positions;  // xyz per vertex
  std::vector<Index> face_offsets{0};
  std::vector<Index> face_vertices;
  std::vector<Index> line_offsets{0};  // polylines (OBJ 'l', VTK line cells)
  std::vector<Index> line_vertices;
  std::vector<CreaseTag> creases;  // OBJ 't crease', feature sidecar
  std::vector<CornerTag> corners;  // OBJ 't corner'
  std::vector<Index> holes;        // OBJ 't hole', feature sidecar "holes": faces left out of the surface
  MeshOptions options;             // OBJ option tags

  Index vertex_count() const { return Index(positions.size() / 3); }
  Index face_count() const { return Index(face_offsets.size()) - 1; }
  Index line_count() const { return Index(line_offsets.size()) - 1; }
};

}  // namespace subdiv
