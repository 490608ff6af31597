#pragma once
// Refined levels as meshes with their arrays, the way every front-end shows them: the
// user's point, cell and face-varying arrays, SubdivKit's own arrays (ArraySelection), hole
// faces left out (as OpenSubdiv leaves them out), split at face-varying seams for viewers
// that show per-point data only. The CLI writes these to .vtp/.pvd, the ParaView filter
// shows them, Python returns their arrays.
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/features/feature_options.h"
#include "framework/io/mesh_data.h"
#include "framework/io/output_level.h"
#include "framework/pipeline/array_selection.h"
#include "framework/primvar/level_data.h"

namespace subdiv {

// Levels `first` to the finest of `h` with their data (data[l] is level l's) and SubdivKit's
// arrays that `arrays` asks for; a user array with the name of one of SubdivKit's (origin,
// valence, level, vertex_class, parent_face, base_face) is kept instead of SubdivKit's.
// `features` (the refinement's boundary mode and crease method) classifies each vertex for
// "vertex_class": 0 smooth, 1 dart, 2 crease, 3 corner. finest_point_data is added to the
// finest level's point data (e.g. limit normals). The OutputLevels point into `meshes`,
// which must outlive them. `consumed`, if given, is `h`, which may then give the levels'
// faces to `meshes` instead of copying them (h is of no use afterwards).
std::vector<OutputLevel> describe_levels(const Hierarchy& h, std::vector<LevelData> data,
                                         const FeatureOptions& features,
                                         const std::vector<DataArray>& finest_point_data, std::vector<MeshData>& meshes,
                                         const ArraySelection& arrays = ArraySelection::all(), int first = 0,
                                         Hierarchy* consumed = nullptr);

// Level L as a mesh with the user's arrays (moved out of `data`): hole faces, their cell
// tuples and face-varying corners left out; creases and corners from L's tags. With
// `donor` (L itself, about to go), its faces move into the mesh instead of being copied.
MeshData level_mesh(const Level& L, LevelData&& data, Level* donor = nullptr);

// Level l as level_mesh makes it, then `extra_point_data` (e.g. limit normals) and
// SubdivKit's arrays that `arrays` asks for, each unless a user array has its name.
// `base_face` is level l's (base_faces_of); `donor` as for level_mesh.
MeshData described_level_mesh(const Hierarchy& h, int l, LevelData&& data, const FeatureOptions& features,
                              std::vector<double> base_face, const ArraySelection& arrays,
                              const std::vector<DataArray>& extra_point_data = {}, Level* donor = nullptr);

// SubdivKit's arrays of level l that `arrays` asks for, added to `mesh` where no array has
// the name. `base_face` is level l's (base_faces_of), moved into "base_face" when asked for.
void add_level_arrays(const Hierarchy& h, int l, MeshData& mesh, const FeatureOptions& features,
                      std::vector<double> base_face, const ArraySelection& arrays);

// The input face each face of level l lies in (-1: none, for faces a dual split makes
// around edges and vertices; hole faces included), from level l - 1's (`above`, unused at
// level 0); base_faces_down_to goes through every level above l.
std::vector<double> base_faces_of(const Hierarchy& h, int l, const std::vector<double>& above);
std::vector<double> base_faces_down_to(const Hierarchy& h, int l);

// `mesh` as level l's output, split at face-varying seams; its arrays move into the result.
OutputLevel output_level(MeshData& mesh, int l);

}  // namespace subdiv
