#pragma once
// Accumulates one stencil row, merging repeated sources. Rows are short (tens of entries),
// so a linear search beats any map.
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

// A block of finished rows (CSR) that later rows may reference as "new points".
struct RowBlock {
  std::vector<Index> offsets{0};
  std::vector<Index> indices;
  std::vector<double> weights;
};

class RowBuilder {
public:
  void clear() { indices_.clear(), weights_.clear(); }
  void add(Index source, double weight) {
    for (size_t i = 0; i < indices_.size(); ++i)
      if (indices_[i] == source) {
        weights_[i] += weight;
        return;
      }
    indices_.push_back(source);
    weights_.push_back(weight);
  }
  void add_row(const RowBlock& block, Index row, double scale) {
    for (Index i = block.offsets[row]; i < block.offsets[row + 1]; ++i)
      add(block.indices[i], scale * block.weights[i]);
  }
  const std::vector<Index>& indices() const { return indices_; }
  const std::vector<double>& weights() const { return weights_; }

private:
  std::vector<Index> indices_;
  std::vector<double> weights_;
};

}  // namespace subdiv
