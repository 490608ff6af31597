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
  if (int(r.boundary) + int(r.crease) + int(r.corner) > 1)
    throw OptionError("a valence analysis is of boundary, crease or corner vertices: make one request for each");
  if (r.corner)
    for (int n : r.valences)
      if (n < 3)
        throw OptionError(fmt::format("{{valences}} {}: a corner has three sharp ring edges, so valence 3 or more", n));
  const CentreKind centre = analysis_centre(*r.scheme);
  std::vector<SurfaceAnalysis> out;
  for (int n : r.valences) {
    LocalConfig c;
    c.centre = centre;
    c.valence = n;
    c.boundary = r.boundary;
    if (r.crease) c.sharp = {0, n / 2};
    if (r.corner) c.sharp = {0, n / 3, 2 * n / 3};
    c.first_step = r.level;
    out.push_back(analyse_configuration(*r.scheme, c, r.options));
  }
  return out;
}

}  // namespace subdiv
