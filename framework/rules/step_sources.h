#pragma once
// Where the step evaluator's rows read their points: parent vertices in src, then
// (numbered from the parent's vertex count) the step's own new points, already written to
// dst (rules/step_evaluator.h).
#include <cstddef>

#include "framework/topology/level.h"

namespace subdiv {

struct StepSources {
  const double* parent;
  const double* children;
  Index parent_count;
  int channels;
  const double* at(Index source) const {
    return source < parent_count ? parent + std::size_t(source) * channels
                                 : children + std::size_t(source - parent_count) * channels;
  }
  const double* child(Index c) const { return children + std::size_t(c) * channels; }
  const double* vertex(Index v) const { return parent + std::size_t(v) * channels; }
};

}  // namespace subdiv
