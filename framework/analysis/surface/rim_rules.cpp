#include "framework/analysis/surface/rim_rules.h"

#include "framework/scheme/step_tables.h"

namespace subdiv {

std::shared_ptr<const Scheme> with_stand_in_rim_rules(const Scheme& scheme) {
  auto rim = std::make_shared<CurveScheme>();
  rim->name = "rim";
  rim->path = scheme.path + " (stand-in rules on a cut neighbourhood's rim)";
  if (scheme.split() == SplitKind::Sqrt3) {  // boundaries trisected every second step
    rim->arity = 3;
    rim->starts = {0, 0, 0};
    rim->weights = {{"1"}, {"2/3", "1/3"}, {"1/3", "2/3"}};
  } else {
    rim->arity = 2;
    rim->starts = {0, 0};
    rim->weights = {{"1"}, {"1/2", "1/2"}};
  }
  auto copy = std::make_shared<Scheme>(scheme);
  copy->curve = std::move(rim);
  return copy;
}

const Scheme& scheme_for_patch_rim(const Scheme& scheme, const LocalConfig& config,
                                   std::shared_ptr<const Scheme>& holder) {
  const bool interior = !config.boundary && config.sharp.empty() && !config.corner;
  if (!interior || has_feature_rules(scheme)) return scheme;
  holder = with_stand_in_rim_rules(scheme);
  return *holder;
}

bool needs_no_feature_rules(const Level& mesh) {
  if (!mesh.manifold()) return false;
  for (Index e = 0; e < mesh.edge_count(); ++e)
    if (mesh.edge_on_boundary(e) || mesh.edge_sharp(e) > 0) return false;
  for (Index v = 0; v < mesh.vertex_count; ++v)
    if (mesh.vertex_sharp(v) > 0) return false;
  return true;
}

const Scheme& scheme_for_cut_rims(const Scheme& scheme, const Level& mesh, std::shared_ptr<const Scheme>& holder) {
  if (has_feature_rules(scheme) || !needs_no_feature_rules(mesh)) return scheme;
  holder = with_stand_in_rim_rules(scheme);
  return *holder;
}

}  // namespace subdiv
