#pragma once
// Accumulates one stencil row, merging repeated sources. Rows are short (tens of entries),
// so a linear search beats any map.
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

// A run of finished rows (CSR).
struct RowBlock {
  std::vector<Index> offsets{0};
  std::vector<Index> indices;
  std::vector<double> weights;
};

// Rows built in fixed-size chunks (one RowBlock each, filled in parallel); row r lives in
// chunk r / chunk_rows. Later rows may reference these as "new points".
struct ChunkedRows {
  Index chunk_rows = 1;
  std::vector<RowBlock> chunks;

  const RowBlock& chunk_of(Index r) const { return chunks[r / chunk_rows]; }
  Index local(Index r) const { return r % chunk_rows; }
  Index row_size(Index r) const {
    const RowBlock& b = chunk_of(r);
    return b.offsets[local(r) + 1] - b.offsets[local(r)];
  }
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
  void add_row(const ChunkedRows& rows, Index row, double scale) {
    const RowBlock& block = rows.chunk_of(row);
    const Index r = rows.local(row);
    for (Index i = block.offsets[r]; i < block.offsets[r + 1]; ++i) add(block.indices[i], scale * block.weights[i]);
  }
  const std::vector<Index>& indices() const { return indices_; }
  const std::vector<double>& weights() const { return weights_; }

private:
  std::vector<Index> indices_;
  std::vector<double> weights_;
};

}  // namespace subdiv
