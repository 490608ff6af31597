#include "framework/engine/level_passes.h"

#include <fmt/format.h>

#include "framework/engine/step_preparation.h"
#include "framework/engine/vertex_parameters.h"
#include "framework/rules/stencil_builder.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

const VertexParameters kNoParameters;

// Whether level l's parameters are read by a pass: as the parent of step l, or as the new
// level of step l - 1 when that step has smoothing passes.
bool parameters_read_on(const std::vector<const Scheme*>& per_level, size_t l) {
  return l < per_level.size() || (l > 0 && per_level[l - 1]->steps.size() > 1);
}

}  // namespace

std::vector<VertexParameters> carried_parameters(const std::vector<const Scheme*>& per_level, const Hierarchy& h,
                                                 const VertexParameters& base) {
  if (base.empty()) return {};
  for (const auto& named : base)
    if (named.second.size() != size_t(h.levels[0].vertex_count)) return {};
  std::vector<VertexParameters> out(h.levels.size());
  out[0] = base;
  // Level l + 1 is carried from level l: every level up to the last one read.
  size_t last = 0;
  for (size_t l = 0; l < h.levels.size(); ++l)
    if (parameters_read_on(per_level, l)) last = l;
  for (size_t l = 0; l < last; ++l) out[l + 1] = carry_vertex_parameters(h.levels[l], h.origins[l], out[l]);
  return out;
}

LevelPasses::LevelPasses(std::span<const SchemeRun> runs, const Hierarchy& h, const RefineOptions& options, int first,
                         int last, const char* caller)
    : h_(h), options_(options), first_(first) {
  const std::vector<const Scheme*> per_level = schemes_per_level(runs);
  step_count_ = int(per_level.size());
  if (per_level.size() + 1 != h.levels.size() || h.origins.size() != per_level.size())
    throw Error(fmt::format("{}: the runs give {} levels but the hierarchy has {}", caller, per_level.size(),
                            h.levels.size() - 1));
  if (first < 0 || last > step_count_ || first > last)
    throw Error(fmt::format("{}: step {} is not in 0..{}", caller, first < 0 ? first : last - 1, step_count_ - 1));
  check_vertex_parameters(runs, h.levels[0], options.vertex_parameters);
  hierarchy_parameters_ = !options.vertex_parameters.empty() && !h.vertex_parameters.empty() &&
                          h.vertex_parameters[0] == options.vertex_parameters;
  for (int step = first; step < last; ++step) {
    step_begin_.push_back(passes_.size());
    const Scheme& scheme = *per_level[size_t(step)];
    const Level& parent = h.levels[size_t(step)];
    const Level& child = h.levels[size_t(step) + 1];
    LevelPass pass;
    pass.scheme = &scheme;
    pass.step = step;
    pass.level = options.first_step + step;
    pass.parent = &parent;
    pass.origins = &h.origins[size_t(step)];
    pass.features_refined = h.features_refined[size_t(step)];
    pass.target_count = child.vertex_count;
    if (scheme.steps.front().nonlinear) {
      passes_.push_back(pass);
      continue;
    }
    pass.rules = &scheme.steps.front();
    pass.parameters = parameters_on(size_t(step));
    passes_.push_back(pass);
    if (scheme.steps.size() == 1) continue;
    identity_.push_back(std::make_unique<ChildOrigins>(identity_origins(child)));
    for (size_t s = 1; s < scheme.steps.size(); ++s) {
      LevelPass smoothing = pass;
      smoothing.rules = &scheme.steps[s];
      smoothing.smoothing = true;
      smoothing.parent = &child;
      smoothing.origins = identity_.back().get();
      smoothing.features_refined = true;
      smoothing.parameters = parameters_on(size_t(step) + 1);
      passes_.push_back(smoothing);
    }
  }
  step_begin_.push_back(passes_.size());
}

std::span<const LevelPass> LevelPasses::of_step(int step) const {
  const size_t i = size_t(step - first_);
  if (step < first_ || i + 1 >= step_begin_.size())
    throw Error(fmt::format("LevelPasses: step {} was not prepared", step));
  return std::span(passes_).subspan(step_begin_[i], step_begin_[i + 1] - step_begin_[i]);
}

// The hierarchy's own (refine_topology carried them once) when they are these options'
// values; otherwise carried here from the base, once per LevelPasses.
const VertexParameters* LevelPasses::parameters_on(size_t level) {
  if (options_.vertex_parameters.empty()) return &kNoParameters;
  if (hierarchy_parameters_) return &h_.vertex_parameters[level];
  if (carried_.empty()) carried_.push_back(std::make_unique<VertexParameters>(options_.vertex_parameters));
  while (carried_.size() <= level) {
    const size_t l = carried_.size() - 1;
    carried_.push_back(std::make_unique<VertexParameters>(
        carry_vertex_parameters(h_.levels[l], h_.origins[l], *carried_.back())));
  }
  return carried_[level].get();
}

}  // namespace subdiv
