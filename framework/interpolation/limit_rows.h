#pragma once
// Building a limit stencil table one row per vertex, in parallel blocks with deterministic
// results: each row's terms are merged by source and sorted, so the table is the same for
// any thread count. A row function may refuse its vertex; the lowest refused vertex wins,
// so the error message is deterministic too.
#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/stencil/stencil_table.h"
#include "framework/util/error.h"

namespace subdiv::detail {

class LimitRow {
public:
  void add(Index source, double weight) {
    for (auto& t : terms_)
      if (t.first == source) {
        t.second += weight;
        return;
      }
    terms_.emplace_back(source, weight);
  }
  void clear() { terms_.clear(); }
  std::vector<std::pair<Index, double>>& terms() { return terms_; }

private:
  std::vector<std::pair<Index, double>> terms_;
};

// row(v, LimitRow&) -> std::string: empty when the row was built, else why not.
template <class RowFunction>
StencilTable build_limit_rows(Index rows, Index sources, RowFunction&& row) {
  constexpr Index kBlock = 1024;
  const Index blocks = (rows + kBlock - 1) / kBlock;
  struct Block {
    std::vector<Index> sizes, indices;
    std::vector<double> weights;
    Index failed = std::numeric_limits<Index>::max();
    std::string why;
  };
  std::vector<Block> out(size_t(std::max<Index>(blocks, 0)));
  tbb::parallel_for(tbb::blocked_range<Index>(0, blocks), [&](const auto& range) {
    LimitRow r;
    for (Index b = range.begin(); b < range.end(); ++b) {
      Block& block = out[b];
      for (Index v = b * kBlock; v < std::min(rows, (b + 1) * kBlock); ++v) {
        r.clear();
        std::string why = row(v, r);
        if (!why.empty()) {
          block.failed = v, block.why = std::move(why);
          break;
        }
        auto& terms = r.terms();
        std::sort(terms.begin(), terms.end());
        block.sizes.push_back(Index(terms.size()));
        for (const auto& [s, w] : terms) block.indices.push_back(s), block.weights.push_back(w);
      }
    }
  });
  for (const Block& block : out)
    if (!block.why.empty()) throw Error(block.why);
  StencilTable t;
  t.source_count = sources;
  t.offsets.reserve(size_t(rows) + 1);
  for (const Block& block : out) {
    for (Index s : block.sizes) t.offsets.push_back(t.offsets.back() + s);
    t.indices.insert(t.indices.end(), block.indices.begin(), block.indices.end());
    t.weights.insert(t.weights.end(), block.weights.begin(), block.weights.end());
  }
  return t;
}

}  // namespace subdiv::detail
