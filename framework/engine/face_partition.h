#pragma once
// Cuts a mesh's faces into pieces of balanced face count for refinement in pieces
// (engine/mesh_pieces.h): a graph partition of the faces (METIS, where SubdivKit was built
// with it), else a split of the faces along a space-filling curve.
#include <span>
#include <string>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

struct FacePartition {
  std::vector<int> face_piece;  // per face: its piece, 0 .. pieces - 1; every piece has a face
  std::string method;           // how it was cut, for the user: "METIS k-way" or "Morton curve"
};

// `pieces` from 1 to the face count (else subdiv::Error naming --pieces). With METIS: a k-way
// partition of the faces' dual graph (faces joined across edges), which keeps the cut, and so
// the ghost faces, small; the same input gives the same pieces. Without it, or where METIS
// leaves a piece empty: the faces in the order of their centroids along a Morton (Z-order)
// curve, cut into runs of equal length (face counts differ by one at most), which keeps
// faces that are close in space together.
FacePartition partition_faces(const Level& level, std::span<const double> positions, int pieces);

// The Morton curve split alone (what partition_faces falls back to).
std::vector<int> partition_faces_along_curve(const Level& level, std::span<const double> positions, int pieces);

// True when this build partitions with METIS.
bool partition_uses_metis();

}  // namespace subdiv
