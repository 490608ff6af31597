#pragma once
// A mesh as read from or written to a file: positions, polygons, polylines and feature tags.
// This is the exchange type between io/ and the engine; it knows nothing of refinement.
#include <cstdint>
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

// What an array means, where a format says it (VTK's active attributes, PLY's property
// names): texture coordinates and colours are refined like any data; normals are not
// (a linear combination of unit normals is not a normal), they are dropped on refinement.
enum class ArrayRole : std::uint8_t { Data, Normals, TextureCoordinates, Color };

// A named array of `components` values per tuple (a vertex, a face). Integer arrays hold
// whole numbers that fit an int (vtkIntArray in .vtp); the others are doubles.
struct DataArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
  bool integer = false;
  ArrayRole role = ArrayRole::Data;
};

// Face-varying data (OBJ's vt and vn): values with their own index per face corner, so that
// neighbouring faces may disagree at a vertex (a UV seam).
struct FaceVaryingArray {
  std::string name;
  int components = 2;
  std::vector<double> values;  // components per value
  std::vector<Index> indices;  // one per face corner, in face_vertices order
  ArrayRole role = ArrayRole::Data;
  Index value_count() const { return components > 0 ? Index(values.size() / size_t(components)) : 0; }
};

struct MeshData {
  std::vector<double> positions;  // xyz per vertex
  // ScratchVectors (util/scratch_vector.h), as a Level's: a refined level's faces move into
  // the mesh written out; readers write every element of what they size.
  ScratchVector<Index> face_offsets{0};
  ScratchVector<Index> face_vertices;
  std::vector<Index> line_offsets{0};  // polylines (OBJ 'l', VTK line cells)
  std::vector<Index> line_vertices;
  std::vector<CreaseTag> creases;  // OBJ 't crease', feature sidecar
  std::vector<CornerTag> corners;  // OBJ 't corner'
  std::vector<Index> holes;        // OBJ 't hole', feature sidecar "holes": faces left out of the surface
  MeshOptions options;             // OBJ option tags
  std::vector<DataArray> point_data;  // one tuple per vertex (the user's arrays)
  std::vector<DataArray> cell_data;   // one tuple per face
  std::vector<FaceVaryingArray> face_varying;
  std::vector<std::string> warnings;  // what a reader left out or changed, one line each

  Index vertex_count() const { return Index(positions.size() / 3); }
  Index face_count() const { return Index(face_offsets.size()) - 1; }
  Index line_count() const { return Index(line_offsets.size()) - 1; }
};

}  // namespace subdiv
