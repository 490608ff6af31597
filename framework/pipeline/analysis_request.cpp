#include "framework/pipeline/analysis_request.h"

#include <fmt/format.h>

#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

void check_valences(const ValenceAnalysisRequest& r) {
  if (r.valences.empty()) throw OptionError("{valences}: give at least one valence");
  const int lowest = r.boundary ? 2 : 3;  // valence 2 exists on boundaries only
  for (int n : r.valences)
    if (n < lowest || n > kMaxAnalysedValence)
      throw OptionError(fmt::format("{{valences}} {}: valences must lie in {}..{}{}", n, lowest, kMaxAnalysedValence,
                                    r.boundary || n != 2 ? "" : " (valence 2 exists at boundaries only)"));
}

}  // namespace

std::vector<SurfaceAnalysis> analyse_valences(const ValenceAnalysisRequest& r) {
  check_valences(r);
  const CentreKind centre = analysis_centre(*r.scheme);
  if (r.boundary && centre != CentreKind::Vertex)
    throw OptionError(fmt::format("{{boundary_analysis}}: {} is analysed at faces (a dual scheme); boundary "
                                  "analysis is done for vertex-centred schemes only",
                                  subdiv::quoted(r.scheme->name)));
  std::vector<SurfaceAnalysis> out;
  for (int n : r.valences) {
    LocalConfig c;
    c.centre = centre;
    c.valence = n;
    c.boundary = r.boundary;
    c.first_step = r.level;
    out.push_back(analyse_configuration(*r.scheme, c, r.options));
  }
  return out;
}

}  // namespace subdiv
