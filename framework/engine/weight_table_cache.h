#pragma once
// Weight tables kept for later refinements with the same scheme: compiling a step's tables
// (muParser over every valence and face size, rules/weight_tables.h) costs about a
// millisecond, nothing for one large level and most of the work when many small pieces are
// refined one after another (limit/adaptive_refine.h: a piece per level).
//
// A table is the step's formulas evaluated at every valence n <= max_n, face size k <=
// max_k, end valences n0, n1 among the valences present and sector sizes up to the level's
// bound; a table made for more valences and larger sizes holds the same values at the
// smaller ones, so a request is served by any kept table that covers it. When none does,
// one is made for the union of the request, what was kept, `seed_valences` and 1 .. max_k
// (a split's face points have the valence of their face's size), so that one table serves
// the levels that follow. The level l is part of the key unless the owner knows that no
// formula reads it.
#include <algorithm>
#include <map>
#include <mutex>
#include <vector>

#include "framework/rules/weight_tables.h"
#include "framework/scheme/step_rules.h"

namespace subdiv {

class WeightTableCache {
public:
  // `level_independent`: no formula of the scheme reads the level l
  // (analysis/surface/limit_evaluation.h: scheme_is_level_dependent). `seed_valences`:
  // valences expected later (ascending), made with the first table.
  explicit WeightTableCache(bool level_independent, std::vector<int> seed_valences = {})
      : level_independent_(level_independent), seed_(std::move(seed_valences)) {}

  // The step's tables covering (max_n, max_k, the level's valences and sector sizes) at
  // `level`; `make(n, k, present)` compiles them when no kept table covers the request.
  template <class Make>
  WeightTables get(const StepRules& step, int level, int max_n, int max_k, const LevelValences& present, Make make) {
    const std::lock_guard lock(mutex_);
    Kept& kept = kept_[{&step, level_independent_ ? 0 : level}];
    const std::vector<int>& valences = present.valences;
    const std::vector<int>& kept_valences = kept.present.valences;
    const std::vector<int>& sizes = present.sector_sizes;
    const std::vector<int>& kept_sizes = kept.present.sector_sizes;
    const bool covered = !kept_valences.empty() && max_n <= kept.max_n && max_k <= kept.max_k &&
                         std::includes(kept_valences.begin(), kept_valences.end(), valences.begin(), valences.end()) &&
                         std::includes(kept_sizes.begin(), kept_sizes.end(), sizes.begin(), sizes.end());
    if (!covered) {
      std::vector<int> all;
      std::set_union(valences.begin(), valences.end(), kept_valences.begin(), kept_valences.end(),
                     std::back_inserter(all));
      std::vector<int> seed = seed_;  // and the valences of the next level's face points
      for (int k = 1; k <= max_k; ++k) seed.push_back(k);
      std::sort(seed.begin(), seed.end());
      seed.erase(std::unique(seed.begin(), seed.end()), seed.end());
      std::vector<int> seeded;
      std::set_union(all.begin(), all.end(), seed.begin(), seed.end(), std::back_inserter(seeded));
      kept.max_n = std::max({max_n, kept.max_n, seeded.empty() ? 0 : seeded.back()});
      kept.max_k = std::max(max_k, kept.max_k);
      std::vector<int> all_sizes;
      std::set_union(sizes.begin(), sizes.end(), kept_sizes.begin(), kept_sizes.end(), std::back_inserter(all_sizes));
      kept.present = {std::move(seeded), std::move(all_sizes)};
      kept.tables = make(kept.max_n, kept.max_k, kept.present);
    }
    return kept.tables;
  }

private:
  struct Kept {
    int max_n = 0, max_k = 0;
    LevelValences present;
    WeightTables tables;
  };
  bool level_independent_;
  std::vector<int> seed_;
  std::mutex mutex_;
  std::map<std::pair<const StepRules*, int>, Kept> kept_;
};

}  // namespace subdiv
