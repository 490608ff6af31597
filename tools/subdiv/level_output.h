#pragma once
// Writes refined levels: .vtp (finest level), .pvd (every level, for ParaView's time
// slider), or a mesh format (.obj, .off, .ply, .stl: finest level, creases kept in .obj).
#include <filesystem>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/engine/refiner.h"
#include "framework/primvar/level_data.h"

namespace subdiv::cli {

// data[l] holds level l's xyz and the user's point and cell arrays, written with their names
// to every format that holds them. `features` (the refinement's boundary mode and crease
// method) classifies each vertex for the per-point "vertex_class" array of .vtp/.pvd
// output: 0 smooth, 1 dart, 2 crease, 3 corner, the rule the vertex takes at its level
// (a user array of the same name as one of SubdivKit's — origin, valence, level,
// vertex_class, parent_face, base_face — is written instead of SubdivKit's).
// finest_point_data is added to the finest level's point data (e.g. limit normals).
// obj_tags: the options written back as OpenSubdiv's tags into .obj output. Hole faces
// (Level::face_hole) are left out of every output, as OpenSubdiv leaves them out.
void write_levels(const std::filesystem::path& out, const Hierarchy& h, const std::vector<LevelData>& data,
                  const FeatureOptions& features, const std::vector<DataArray>& finest_point_data = {},
                  const MeshOptions& obj_tags = {});

// What write_levels writes to .vtp/.pvd, without a file: every level with the user's arrays
// and SubdivKit's (as write_levels says), split at face-varying seams. The OutputLevels point
// into `meshes`, which must outlive them. The ParaView plugin (plugins/paraview) shows these.
std::vector<OutputLevel> describe_levels(const Hierarchy& h, const std::vector<LevelData>& data,
                                         const FeatureOptions& features,
                                         const std::vector<DataArray>& finest_point_data,
                                         std::vector<MeshData>& meshes);

// The output extensions write_levels accepts, for help texts and early checks.
void check_output_path(const std::filesystem::path& out);

}  // namespace subdiv::cli
