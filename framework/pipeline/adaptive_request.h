#pragma once
// Feature-adaptive refinement as every front-end asks for it (`subdiv refine --adaptive L`,
// `subdiv evaluate --adaptive L`, Python's subdivkit.refine_adaptive): the mesh, scheme and
// shape options of a RefineRequest, loaded as a refinement loads them (prepare_refinement),
// then limit/adaptive_refine.h up to the request's level with an optional tolerance.
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/limit/adaptive_refine.h"
#include "framework/pipeline/evaluate_request.h"
#include "framework/pipeline/refine_request.h"

namespace subdiv {

// The deepest level adaptive refinement goes to (every front-end's range).
constexpr int kMaxAdaptiveLevel = 12;

struct AdaptiveRequest {
  RefineRequest refine;   // the mesh, scheme, shape options; `levels` is the cap L
  double tolerance = 0;   // > 0: also split faces farther than this from the limit surface
  bool limit = false;     // every vertex on the limit surface
  bool uniform = false;   // the tolerance splits every face: AdaptiveOptions::uniform
  // Transition faces as polygons or as triangles and quads (limit/adaptive_transitions.h).
  AdaptiveTransitions transitions = AdaptiveTransitions::Polygons;
};

// The choice a front-end's spelling names ("polygons", "triangles"); throws
// subdiv::OptionError naming {transitions} for another.
AdaptiveTransitions transitions_from_name(const std::string& name);

struct AdaptiveResult {
  AdaptiveMesh mesh;
  // The mesh's point arrays placed like the positions (names and components; the values
  // are in mesh.data, side by side). Integer arrays (ids, labels) are left out.
  std::vector<DataArray> point_arrays;
  // The mesh's face-varying channels (texture coordinates, ...) in the request's
  // face-varying interpolation mode (primvar/face_varying.h), normals left out with a note.
  // With limit positions each corner's value is the channel's own limit at the corner's (base
  // face, u, v), as `subdiv evaluate` gives it (one value per corner); without, the channels
  // are refined with the faces, each corner's value its level's (limit/adaptive_refine.h:
  // AdaptiveFaceVarying; values shared within a UV island).
  std::vector<FaceVaryingArray> face_varying;
  std::string scheme_label;
  int levels = 0;
  std::vector<std::string> warnings;  // the mesh reader's, clean-up's
  std::vector<std::string> notes;     // feature files and angles applied
};

// A rational mesh (weights, rational_weights.h) is refined as its homogeneous points and
// projected, with `limit` onto the rational limit surface.
// Throws subdiv::Error naming the mesh (a sequence of schemes, a split other than the
// binary quad and triangle splits, a scheme whose limit cannot be evaluated when a
// tolerance or limit positions are asked for), or subdiv::OptionError naming an option
// ({levels} outside 0..12, {tolerance} negative or not a number, or given with rational
// weights: it would be measured in homogeneous coordinates).
AdaptiveResult refine_adaptive_request(AdaptiveRequest request);

// The mesh, scheme and shape options of an evaluation's request (subdiv evaluate --adaptive).
AdaptiveRequest adaptive_request_from(EvaluateRequest evaluation, int levels, double tolerance, bool limit);

// The adaptive mesh as a mesh to write: cell arrays face_level and base_face, the point
// arrays (`point_arrays` as AdaptiveResult has them, their values taken from mesh.data) and
// the face-varying arrays.
MeshData adaptive_mesh_data(AdaptiveMesh&& mesh, std::vector<DataArray> point_arrays = {},
                            std::vector<FaceVaryingArray> face_varying = {});

// One line for people: "N faces, levels 0..L (uniform level L: M); faces split per level: a b c".
std::string adaptive_summary(const AdaptiveResult& result);

}  // namespace subdiv
