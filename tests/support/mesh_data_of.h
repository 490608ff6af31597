#pragma once
// A test mesh (support/test_meshes.h) as the io layer's MeshData: positions and faces only,
// as a reader would give them for a file without tags or arrays.
#include "framework/io/mesh_data.h"
#include "support/test_meshes.h"

namespace subdiv::test {

inline MeshData mesh_data(const Mesh& m) {
  MeshData d;
  d.positions = m.positions;
  d.face_offsets.assign(m.offsets.begin(), m.offsets.end());
  d.face_vertices.assign(m.corners.begin(), m.corners.end());
  return d;
}

}  // namespace subdiv::test
