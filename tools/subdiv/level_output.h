#pragma once
// Writes refined levels: .vtp (finest level), .pvd (every level, for ParaView's time
// slider), or a mesh format (.obj, .off, .ply, .stl: finest level, creases kept in .obj).
// The levels are described by the pipeline (framework/pipeline/level_description.h).
#include <filesystem>
#include <string_view>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/util/atomic_file.h"
#include "framework/engine/refiner.h"
#include "framework/pipeline/level_description.h"
#include "framework/primvar/level_data.h"
#include "output_options.h"

namespace subdiv::cli {

// `out` was checked by check_output_path before the work (its format and its place).
// data[l] holds level l's xyz and the user's point and cell arrays, written with their names
// to every format that holds them. `features` (the refinement's boundary mode and crease
// method) classifies each vertex for the per-point "vertex_class" array of .vtp/.pvd
// output: 0 smooth, 1 dart, 2 crease, 3 corner, the rule the vertex takes at its level
// (a user array of the same name as one of SubdivKit's — origin, valence, level,
// vertex_class, parent_face, base_face — is written instead of SubdivKit's).
// finest_point_data is added to the finest level's point data (e.g. limit normals).
// obj_tags: the options written back as OpenSubdiv's tags into .obj output. Hole faces
// (Level::face_hole) are left out of every output, as OpenSubdiv leaves them out.
// `choice`: which of SubdivKit's arrays .vtp/.pvd hold and how they are compressed
// (output_options.h). `h` and `data` are used up: the written levels' faces and values move
// into the output instead of being copied.
void write_levels(const std::filesystem::path& out, Hierarchy&& h, std::vector<LevelData> data,
                  const FeatureOptions& features, const std::vector<DataArray>& finest_point_data = {},
                  const MeshOptions& obj_tags = {}, const OutputChoice& choice = {});

// One piece of a refinement in pieces (engine/mesh_pieces.h), as write_levels writes a .vtp:
// the finest level of the piece's hierarchy `h` with only the faces `piece` owns
// (finest_owner, per face) and their vertices; crease edges where the piece owns the face
// in their first slot, so that no crease is written twice. "base_face" numbers the whole
// mesh's faces (base_faces: per face of the piece's base level). Staged in `staged`.
void write_piece(StagedFiles& staged, const std::filesystem::path& target, const Hierarchy& h,
                 std::vector<LevelData> data, const FeatureOptions& features, const std::vector<Index>& base_faces,
                 const std::vector<int>& finest_owner, int piece, const OutputChoice& choice = {});

// Refuses an output write_levels cannot write: an extension it has no writer for, or a
// place no file can be created (checked by creating one), before any work.
void check_output_path(const std::filesystem::path& out);

// Refuses an output that is the input mesh, or a folder the output rewrites (a .pvd's
// levels, a .pvtp's pieces) that holds it, unless `force`: the control mesh would be lost.
// `option` names the output's option in the message.
void check_output_not_input(const std::filesystem::path& input, const std::filesystem::path& out, bool force,
                            std::string_view option = "-o");

}  // namespace subdiv::cli
