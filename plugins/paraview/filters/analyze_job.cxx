#include "analyze_job.h"

#include <fmt/format.h>

#include "framework/pipeline/analysis_request.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"
#include "scheme_choice.h"

namespace subdiv::paraview {
namespace {

// The valences `subdiv analyze` takes: 2 (inside as on a boundary) to kMaxAnalysedValence.
void check_valences(const AnalyzeRequest& r, const std::string& source) {
  if (r.min_valence < 2 || r.max_valence > kMaxAnalysedValence || r.min_valence > r.max_valence)
    throw Error(fmt::format("{}: Valences {}..{}: give a range from 2 to {} with the first no larger than the last",
                            source, r.min_valence, r.max_valence, kMaxAnalysedValence));
}

}  // namespace

std::vector<SurfaceAnalysis> analyze_valences(const AnalyzeRequest& r, const std::string& source) {
  check_valences(r, source);
  if (scheme_kind(r.scheme) != "surface")
    throw Error(fmt::format("{}: {} is a curve scheme; the characteristic map and the spectrum at extraordinary "
                            "vertices belong to surface schemes (`subdiv analyze {}` analyses curve schemes)",
                            source, subdiv::quoted(r.scheme), subdiv::escaped(r.scheme)));
  ValenceAnalysisRequest request;
  request.scheme = load_scheme(r.scheme, parameter_overrides(r.parameters));
  for (int n = r.min_valence; n <= r.max_valence; ++n) request.valences.push_back(n);
  request.options.features.boundary = r.boundary;
  request.boundary = r.vertices == AnalysedVertices::Boundary;
  request.crease = r.vertices == AnalysedVertices::Crease;
  request.options.characteristic_map = true;
  return analyse_valences(request);
}

}  // namespace subdiv::paraview
