#include "framework/interpolation/analysed_limit.h"

#include <fmt/format.h>

#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {

AnalysedLimit::AnalysedLimit(std::shared_ptr<const Scheme> scheme, const FeatureOptions& features)
    : scheme_(std::move(scheme)) {
  LimitOptions o;
  o.features = features;
  limits_ = std::make_shared<SchemeLimits>(*scheme_, o);
}

std::string AnalysedLimit::name() const { return fmt::format("limit masks of {}'s eigen-analysis", scheme_->name); }

StencilTable AnalysedLimit::stencils_at(const Level& level, int step) const {
  LimitStencils s = limits_->stencils(level, step);
  if (s.first_approximate != kNone)
    throw Error(fmt::format("{}: vertex {} has no exact limit mask ({}){}", name(), s.first_approximate,
                            s.first_reason,
                            s.approximate > 1 ? fmt::format("; {} vertices in all", s.approximate) : ""));
  return std::move(s.position);
}

}  // namespace subdiv
