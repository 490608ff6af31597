#pragma once
// A stencil table: row r gives child value r as a weighted sum of source values
// (CSR: offsets, indices, weights). Topology is refined once; geometry is this product.
#include <span>
#include <vector>

#include "framework/topology/level.h"

namespace subdiv {

struct StencilTable {
  Index source_count = 0;
  std::vector<Index> offsets{0};
  std::vector<Index> indices;
  std::vector<double> weights;

  Index row_count() const { return Index(offsets.size()) - 1; }
  int row_size(Index r) const { return offsets[r + 1] - offsets[r]; }

  // dst[r*channels + c] = sum_i w_i * src[idx_i*channels + c]. Rows run in parallel;
  // each row is summed in its stored order, so results are the same for any thread count.
  void apply(std::span<const double> src, std::span<double> dst, int channels) const;
  std::vector<double> apply(std::span<const double> src, int channels) const;
  // Only the rows `rows`, in that order: out[k*channels + c] is row rows[k]'s value, the same
  // bits as apply() gives it (each row summed in its stored order), without computing or
  // storing the rows no one reads (a piece's ghost rows, engine/mesh_pieces.h).
  std::vector<double> apply_rows(std::span<const double> src, std::span<const Index> rows, int channels) const;
};

// Rows of `second` (over the rows of `first`) expanded into rows over first's sources:
// the table of applying first, then second.
StencilTable compose(const StencilTable& first, const StencilTable& second);

}  // namespace subdiv
