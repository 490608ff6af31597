#include "framework/pipeline/analysis_request.h"

#include <fmt/format.h>

#include "framework/util/option_spelling.h"

namespace subdiv {
namespace {

void check_valences(const ValenceAnalysisRequest& r) {
  if (r.valences.empty()) throw OptionError("{valences}: give at least one valence");
  // Valence 2 exists at boundaries and inside quad meshes (two quads sharing two edges);
  // inside a triangle mesh the analysis says why it cannot (make_vertex_patch).
  for (int n : r.valences)
    if (n < 2 || n > kMaxAnalysedValence)
      throw OptionError(fmt::format("{{valences}} {}: valences must lie in 2..{}", n, kMaxAnalysedValence));
}

}  // namespace

std::vector<SurfaceAnalysis> analyse_valences(const ValenceAnalysisRequest& r) {
  check_valences(r);
  if (r.boundary && r.crease)
    throw OptionError("a valence analysis is of boundary vertices or of crease vertices: make one request for each");
  const CentreKind centre = analysis_centre(*r.scheme);
  std::vector<SurfaceAnalysis> out;
  for (int n : r.valences) {
    LocalConfig c;
    c.centre = centre;
    c.valence = n;
    c.boundary = r.boundary;
    if (r.crease) c.sharp = {0, n / 2};
    c.first_step = r.level;
    out.push_back(analyse_configuration(*r.scheme, c, r.options));
  }
  return out;
}

}  // namespace subdiv
