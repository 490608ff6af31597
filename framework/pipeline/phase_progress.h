#pragma once
// A phase of long work told to a front-end (a request's `progress` and `progress_fraction`):
// its name as it starts, then, while the object lives, the shares of it that the library's
// loops tell (util/step_progress.h) as the bar's fraction. Either callback may be empty.
#include <functional>
#include <optional>
#include <string>

#include "framework/util/step_progress.h"

namespace subdiv {

class PhaseProgress {
public:
  // `fraction` must outlive this object (the scope keeps a pointer to it).
  PhaseProgress(const std::function<void(const std::string&)>& say, const std::function<void(double)>& fraction,
                const std::string& phase) {
    if (say) say(phase);
    if (fraction) scope_.emplace(fraction);
  }

private:
  std::optional<StepProgressScope> scope_;
};

}  // namespace subdiv
