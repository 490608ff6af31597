#include "limit_job.h"

#include "framework/pipeline/adaptive_request.h"
#include "framework/pipeline/evaluate_request.h"
#include "framework/pipeline/limit_mesh.h"
#include "framework/pipeline/thread_limit.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "scheme_choice.h"

namespace subdiv::paraview {
namespace {

// The filter's property names for the pipeline's options, in messages and notes.
const OptionSpelling& filter_spelling() {
  static const OptionSpelling spelling = {
      {"scheme", "Scheme"},          {"levels", "Adaptive Levels"},     {"tolerance", "Tolerance"},
      {"samples", "Samples"},       {"transitions", "Transitions"},
      {"boundary", "Boundary"},      {"crease_method", "Crease Method"}, {"feature_angle", "Feature Angle"},
      {"limit", "Limit Positions"},  {"threads", "Threads"},            {"param", "Parameters"},
      {"scheme_list", "the Scheme menu"}};
  return spelling;
}

EvaluateRequest evaluate_request(const MeshData& mesh, const LimitSettings& s, const std::string& source) {
  EvaluateRequest request;
  request.mesh = mesh;
  request.mesh_name = source;
  request.scheme.text = s.scheme;
  request.scheme.parameters = parameter_overrides(s.parameters);
  request.shape.boundary = s.features.boundary;
  request.shape.crease_method = s.features.crease_method;
  request.feature_angle = s.feature_angle;
  return request;
}

LimitMesh run(const MeshData& mesh, const LimitSettings& s, const std::string& source) {
  LimitMesh out;
  if (s.mode == LimitMode::Adaptive) {
    AdaptiveRequest request =
        adaptive_request_from(evaluate_request(mesh, s, source), s.adaptive_levels, s.tolerance, s.limit_positions);
    if (s.triangle_transitions) request.transitions = AdaptiveTransitions::Triangles;
    AdaptiveResult r = refine_adaptive_request(std::move(request));
    out.notes = std::move(r.warnings);
    out.notes.insert(out.notes.end(), r.notes.begin(), r.notes.end());
    out.mesh = adaptive_mesh_data(std::move(r.mesh), std::move(r.point_arrays), std::move(r.face_varying));
    return out;
  }
  const PreparedEvaluation prepared = prepare_evaluation(evaluate_request(mesh, s, source));
  out.notes = prepared.warnings;
  out.notes.insert(out.notes.end(), prepared.notes.begin(), prepared.notes.end());
  out.mesh = sampled_limit_mesh(prepared, s.samples);
  out.notes.insert(out.notes.end(), out.mesh.warnings.begin(), out.mesh.warnings.end());
  return out;
}

}  // namespace

LimitMesh limit_mesh(const MeshData& mesh, const LimitSettings& s, const std::string& source) {
  const ThreadLimit threads(s.threads);
  if (mesh.face_count() == 0)
    throw Error(source + ": the input has no polygons; give it a surface (e.g. Extract Surface)");
  try {
    LimitMesh out = run(mesh, s, source);
    // Normals are left out without a note, as SubdivKit Refine leaves them: most of
    // ParaView's sources have them.
    std::erase_if(out.notes, [](const std::string& note) { return note.find("holds normals") != std::string::npos; });
    for (std::string& note : out.notes) note = spell_options(note, filter_spelling());
    return out;
  } catch (const OptionError& e) {
    throw Error(e.spelled(filter_spelling()));
  }
}

}  // namespace subdiv::paraview
