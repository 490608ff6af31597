#pragma once
// The product path once: read nothing, write nothing, but everything between — clean-up,
// scheme loading, shape options from the request or the mesh's tags, features from tags,
// files and angles, the memory guard, topology, each level's point, cell and face-varying
// data, limit positions and normals. Every front-end translates its input into a
// RefineRequest, calls refine(), and translates the RefineResult into files, NumPy arrays or
// vtkPolyData (level_description.h describes the levels for all of them).
#include "framework/pipeline/refine_request.h"

namespace subdiv {

// Everything up to topology: throws subdiv::Error naming the request's mesh, or
// subdiv::OptionError (option_spelling.h) naming one of its options. Messages and notes
// name options with placeholders ("{levels}") that front-ends spell in their own words.
PreparedRefinement prepare_refinement(RefineRequest& request);

// What refine_level_data left out, and the notes that say so.
struct LevelDataNotes {
  std::vector<std::string> dropped_arrays;  // point and face-varying arrays holding normals
  std::vector<std::string> notes;           // one per array, with placeholders (option_spelling.h)
};

// The data of every level of `h` (refined from `mesh`'s base level with `options`): point
// arrays with the positions by the scheme's rules (normals left out: a mix of unit normals
// is no normal), integer arrays by origin, cell arrays inherited, face-varying arrays by
// refine_face_varying. Only the finest level's unless the request keeps all levels. Used
// whole and per piece (engine/mesh_pieces.h).
std::vector<LevelData> refine_level_data(const PreparedRefinement& prepared, const Hierarchy& h, const MeshData& mesh,
                                         const RefineOptions& options, const RefineRequest& request,
                                         LevelDataNotes& said);

// Whether the prepared mesh's last level can be built with its faces only
// (RefineOptions::faces_only_last_level), as run_refinement decides it: for a caller that
// refines the prepared mesh itself (in pieces, tools/subdiv/piece_refine.cpp).
bool last_level_faces_suffice(const RefineRequest& request, const PreparedRefinement& prepared);

// The rest: memory check, topology, level data, limits.
RefineResult run_refinement(PreparedRefinement&& prepared, const RefineRequest& request);

// Both.
RefineResult refine_mesh(RefineRequest request);

}  // namespace subdiv
