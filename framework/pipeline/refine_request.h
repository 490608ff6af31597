#pragma once
// A refinement as every front-end asks for it (the command line's `subdiv refine`, Python's
// subdivkit.refine, ParaView's "SubdivKit Refine"): a mesh with its arrays, a scheme, the
// shape options, and what to produce. refine_pipeline.h runs it.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/engine/refiner.h"
#include "framework/features/feature_options.h"
#include "framework/io/mesh_data.h"
#include "framework/pipeline/array_selection.h"
#include "framework/primvar/face_varying.h"
#include "framework/primvar/level_data.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/scheme/scheme_sequence.h"

namespace subdiv {

// Where the scheme comes from: a registered name, a .json path or a sequence "A:1,B:3"
// (each name with its levels; one without :N takes the rest), or a scheme file's JSON text.
struct SchemeSource {
  std::string text;  // required: the request names its scheme
  bool is_json_text = false;
  std::string label;               // names JSON text in messages
  ParameterOverrides parameters;   // name -> value, over the scheme's defaults
};

// The options that change the limit surface (OpenSubdiv's Sdc::Options). Unset: the mesh
// file's option tags (OBJ `t interpolateboundary`, ...) if it has them, else the default.
struct ShapeChoices {
  std::optional<BoundaryInterpolation> boundary;  // default edges-and-corners
  std::optional<CreaseMethod> crease_method;      // default uniform
  std::optional<FaceVaryingLinear> face_varying;  // default all (bilinear), as OpenSubdiv
  // OpenSubdiv's smooth triangles (TRI_SUB_SMOOTH): the scheme parameter "triangles" set to
  // "smooth"; refused for a scheme without that parameter. Unset: the mesh's tag, if any.
  bool smooth_triangles = false;
};

// The largest start level (RefineRequest::start_level): level-dependent state is computed
// level by level up to it, and no refinement history is longer. Every front-end's range.
constexpr int kMaxStartLevel = 100;

struct RefineRequest {
  // The mesh: read from `mesh_file` (any format io/mesh_read.h reads) when it is given, after
  // the scheme is loaded; otherwise `mesh`, with its tags and point/cell/face-varying arrays.
  std::string mesh_file;
  MeshData mesh;
  std::string mesh_name;  // names the mesh in messages (a file name, "mesh", the filter's name)
  SchemeSource scheme;
  int levels = 1;
  // Whether `levels` was asked for: a sequence whose own counts add up to another total is
  // then refused. Otherwise a sequence's last scheme without :N takes the rest of `levels`.
  bool levels_given = false;
  int start_level = 0;  // steps the input has already been through (RefineOptions::first_step)
  ShapeChoices shape;

  std::string feature_file;    // a feature sidecar (io/feature_file.h) applied after the mesh's tags
  double feature_angle = -1;   // degrees: sharper edges become infinitely sharp creases; < 0: off
  // Per-vertex scheme parameters, one value per input vertex in its order: given, or read
  // from files (parameter name -> file, io/vertex_values.h).
  VertexParameters vertex_parameters;
  std::map<std::string, std::string> vertex_parameter_files;
  // The point array of rational weights (rational_weights.h): refinement carries (w·p, w)
  // and projects. Empty: OBJ's fourth coordinate or an array named "weight", if any.
  std::string weights_array;

  // What to produce.
  bool keep_all_levels = true;   // false: only the finest level's data is kept
  bool limit_positions = false;  // the finest level moved to the limit surface, with normals
  bool limit_normals = false;    // the finest level's limit normals, vertices where they are
  // SubdivKit's arrays the levels will be described with (level_description.h); unset when
  // the output holds none of them (mesh formats, Python), which lets the last level be built
  // with faces only where nothing else needs its edges.
  std::optional<ArraySelection> described_arrays;

  double memory_budget = 0;                       // bytes; 0: what the machine lets this process have
  std::string memory_advice = "ask for fewer levels";  // ends the message when it does not fit
  std::function<void(const std::string& phase)> progress;  // told each phase as it starts
  // Told the share of the long work done so far, 0 to 1, from the thread that made the
  // request: 0 when the levels' values start, then after each level (by its faces). A
  // front-end draws a bar with a time estimate from it (tools/subdiv/progress.h).
  std::function<void(double done)> progress_fraction;
};

// A refinement prepared: the mesh cleaned, the scheme loaded, the base level tagged.
struct PreparedRefinement {
  SchemeSequence sequence;
  std::string scheme_label;  // the scheme as the request named it
  MeshData mesh;             // the request's mesh without unused vertices
  Level base;
  RefineOptions options;     // shape options in force, start level, vertex parameters
  FaceVaryingLinear face_varying = FaceVaryingLinear::All;
  MeshOptions tags;          // the options in force, as OpenSubdiv's tags (OBJ output keeps them)
  std::string weights_name;  // the rational weights' point array; empty: none
  bool rational = false;     // weights that are not all 1: positions refined as (w·p, w)
  std::vector<std::string> warnings;  // the mesh reader's, clean-up's
  std::vector<std::string> notes;     // what was applied: feature files and angles
};

struct RefineResult {
  SchemeSequence sequence;
  std::string scheme_label;
  FeatureOptions features;
  MeshOptions tags;
  Hierarchy hierarchy;
  std::vector<LevelData> levels;              // levels[l]: level l's data; empty where not kept
  std::vector<DataArray> finest_point_data;   // limit normals, limit_exact, normal_exact
  // With limit positions or normals: how many were exact and why others were approximated
  // (its positions and normals are in the finest level and finest_point_data).
  std::optional<LimitResult> limit;
  std::string limit_note;  // what the limits approximated and why; empty when all are exact
  // Limit normals left out (a scheme that is not C1, limit_arrays.h) and why; also in `warnings`.
  std::vector<std::string> limit_warnings;
  std::vector<std::string> warnings;          // the mesh's, clean-up's, the topology's, the limits'
  // What was applied (feature files and angles), arrays not carried; options named with
  // placeholders (option_spelling.h).
  std::vector<std::string> notes;
  std::vector<std::string> dropped_arrays;    // point/face-varying arrays not carried (normals)
};

}  // namespace subdiv
