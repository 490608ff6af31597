#include "framework/analysis/surface/rim_rules.h"

#include "framework/scheme/step_tables.h"

namespace subdiv {

const Scheme& scheme_for_patch_rim(const Scheme& scheme, const LocalConfig& config,
                                   std::shared_ptr<const Scheme>& holder) {
  const bool interior = !config.boundary && config.sharp.empty() && !config.corner;
  if (!interior || has_feature_rules(scheme)) return scheme;
  auto rim = std::make_shared<CurveScheme>();
  rim->name = "rim";
  rim->path = scheme.path + " (the analysis' stand-in rules on the synthetic patch's rim)";
  rim->arity = 2;
  rim->starts = {0, 0};
  rim->weights = {{"1"}, {"1/2", "1/2"}};
  auto copy = std::make_shared<Scheme>(scheme);
  copy->curve = std::move(rim);
  holder = std::move(copy);
  return *holder;
}

}  // namespace subdiv
