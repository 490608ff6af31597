#include "framework/interpolation/analysed_limit.h"

#include <fmt/format.h>

#include "framework/analysis/surface/rim_rules.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/step_tables.h"
#include "framework/util/error.h"

namespace subdiv {

AnalysedLimit::AnalysedLimit(std::shared_ptr<const Scheme> scheme, const FeatureOptions& features)
    : scheme_(std::move(scheme)) {
  LimitOptions o;
  o.features = features;
  limits_ = std::make_shared<SchemeLimits>(*scheme_, o);
  if (!has_feature_rules(*scheme_)) {
    rim_scheme_ = with_stand_in_rim_rules(*scheme_);
    rim_limits_ = std::make_shared<SchemeLimits>(*rim_scheme_, o);
  }
}

std::string AnalysedLimit::name() const { return fmt::format("limit masks of {}'s eigen-analysis", scheme_->name); }

StencilTable AnalysedLimit::stencils_at(const Level& level, int step) const {
  const bool stand_in_rims = rim_limits_ && needs_no_feature_rules(level);
  LimitStencils s = (stand_in_rims ? rim_limits_ : limits_)->stencils(level, step);
  if (s.first_approximate != kNone)
    throw Error(fmt::format("{}: vertex {} has no exact limit mask ({}){}", name(), s.first_approximate,
                            s.first_reason,
                            s.approximate > 1 ? fmt::format("; {} vertices in all", s.approximate) : ""));
  return std::move(s.position);
}

}  // namespace subdiv
