#include "framework/limit/cut_weight_tables.h"

#include <numeric>

#include "framework/scheme/scheme.h"

namespace subdiv {

std::unique_ptr<WeightTableCache> cut_weight_tables(const Scheme& scheme, bool level_independent) {
  std::vector<int> seed(scheme.split() == SplitKind::Triangle ? 6 : 4);
  std::iota(seed.begin(), seed.end(), 1);
  return std::make_unique<WeightTableCache>(level_independent, std::move(seed));
}

}  // namespace subdiv
