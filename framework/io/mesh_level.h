#pragma once
// Between the file-level MeshData and the engine's Level: topology plus feature tags.
#include <string>

#include "framework/io/mesh_data.h"
#include "framework/topology/level.h"

namespace subdiv {

// Builds the level and applies crease and corner tags. `source` (the file name) prefixes
// every message; a crease naming a non-existent edge or a negative sharpness is refused.
Level level_from_mesh(const MeshData& mesh, const std::string& source);

// Positions, faces and the level's feature tags (sharp interior edges as creases, sharp
// vertices as corners) as a MeshData for writing. Boundary edges are sharp by topology and
// are not written as creases.
MeshData mesh_from_level(const Level& level, std::vector<double> positions);

// Throws subdiv::Error "<source>: ..." when every face of `level` is a hole: nothing would
// be left to refine or write (an empty output file that looks like success).
void require_some_face_outside_holes(const Level& level, const std::string& source);

// Per-corner values (face-varying indices) of the level's faces that are not holes, in the
// order mesh_from_level writes those faces.
std::vector<Index> corners_outside_holes(const Level& level, const std::vector<Index>& per_corner);

}  // namespace subdiv
