#include "refine_job.h"

#include <fmt/format.h>

#include "framework/pipeline/level_description.h"
#include "framework/util/option_spelling.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/pipeline/thread_limit.h"
#include "framework/util/error.h"
#include "scheme_choice.h"

namespace subdiv::paraview {
namespace {

// The filter's property names for the pipeline's options, in messages and notes.
const OptionSpelling& filter_spelling() {
  static const OptionSpelling spelling = {{"scheme", "Scheme"},       {"levels", "Levels"},
                                          {"boundary", "Boundary"},   {"crease_method", "Crease Method"},
                                          {"feature_angle", "Feature Angle"}, {"limit", "Limit Positions"},
                                          {"normals", "Limit Positions"},     {"threads", "Threads"},
                                          {"param", "Parameters"},            {"scheme_list", "the Scheme menu"}};
  return spelling;
}

RefineRequest pipeline_request(const MeshData& mesh, const RefineSettings& r, const std::string& source) {
  RefineRequest request;
  request.mesh = mesh;
  request.mesh_name = source;
  request.scheme.text = r.scheme;
  request.scheme.parameters = parameter_overrides(r.parameters);
  request.levels = r.levels;
  request.shape.boundary = r.features.boundary;
  request.shape.crease_method = r.features.crease_method;
  request.feature_angle = r.feature_angle;
  request.limit_positions = r.limit;
  request.described_arrays = ArraySelection::all();
  request.progress_fraction = r.progress;
  return request;
}

}  // namespace

RefinedLevels refine_levels(const MeshData& input, const RefineSettings& r, const std::string& source) {
  const ThreadLimit threads(r.threads);
  if (input.face_count() == 0)
    throw Error(fmt::format("{}: the input has no polygons to refine; give it a surface (e.g. Extract Surface)",
                            source));
  RefinedLevels out;
  RefineResult result;
  try {
    result = refine_mesh(pipeline_request(input, r, source));
  } catch (const OptionError& e) {
    throw Error(e.spelled(filter_spelling()));
  }
  out.notes = std::move(result.warnings);
  // Normals are left out without a note: most of ParaView's sources have them, and a
  // warning on every refinement would bury the ones that matter (docs/paraview.md says so).
  for (const auto& note : result.notes)
    if (note.find("holds normals") == std::string::npos) out.notes.push_back(spell_options(note, filter_spelling()));
  if (!result.limit_note.empty()) out.notes.push_back(spell_options(result.limit_note, filter_spelling()));
  out.levels = describe_levels(result.hierarchy, std::move(result.levels), result.features, result.finest_point_data,
                               out.meshes);
  return out;
}

}  // namespace subdiv::paraview
