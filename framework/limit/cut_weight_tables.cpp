#include "framework/limit/cut_weight_tables.h"

#include <numeric>

#include "framework/scheme/scheme.h"

namespace subdiv {

std::unique_ptr<WeightTableCache> cut_weight_tables(const Scheme& scheme) {
  std::vector<int> seed(scheme.split() == SplitKind::Triangle ? 6 : 4);
  std::iota(seed.begin(), seed.end(), 1);
  // Keyed by level: a level-dependent scheme is refused before any cut is refined, and the
  // cuts' levels count from 0 anyway.
  return std::make_unique<WeightTableCache>(false, std::move(seed));
}

}  // namespace subdiv
