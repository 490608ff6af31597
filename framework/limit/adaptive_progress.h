#pragma once
// The progress bar's share of each level of an adaptive refinement. A level's work grows with
// the faces it splits, which a tolerance near 0 multiplies by up to four per level, so equal
// shares per level would tell "69 %, about 4 s left" an hour before the end. Each level takes,
// of the share still left, what its faces are of the faces still expected if the last growth
// goes on to the last level: exact for geometric growth, and never moving the bar backwards.
#include <algorithm>
#include <utility>

namespace subdiv {

class AdaptiveProgress {
public:
  // `levels` levels, then (when `limit_phase`) the limit positions, which cost about one
  // more level's faces; `growth` is the guess before two levels are seen.
  AdaptiveProgress(int levels, bool limit_phase, double growth)
      : levels_(levels), limit_phase_(limit_phase), growth_(std::clamp(growth, 1.0, 4.0)) {}

  // The share [begin, end] of the whole that level `level`, splitting `faces` faces, takes.
  std::pair<double, double> level_span(int level, double faces) {
    if (previous_faces_ > 0 && faces > 0) growth_ = std::clamp(faces / previous_faces_, 1.0, 4.0);
    previous_faces_ = faces;
    double expected = 0, term = 1;  // this level's faces counted as 1
    for (int l = level; l < levels_ + (limit_phase_ ? 1 : 0); ++l, term *= growth_) expected += term;
    const double begin = done_;
    done_ += (1 - done_) / std::max(expected, 1.0);
    return {begin, done_};
  }

  // What the limit positions take: the rest.
  std::pair<double, double> limit_span() const { return {done_, 1.0}; }

private:
  int levels_;
  bool limit_phase_;
  double growth_;
  double previous_faces_ = 0;
  double done_ = 0;
};

}  // namespace subdiv
