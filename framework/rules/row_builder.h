#pragma once
// Accumulates one stencil row, merging repeated sources. Rows are mostly short (tens of
// entries): a small open-addressing table finds a repeated source in one or two probes. Rows
// longer than it (a stencil over the ring of a vertex of valence 2,000) keep their further
// sources in a hash map, so that a row of m sources costs O(m), not O(m^2).
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "framework/topology/level.h"
#include "framework/util/bulk_memory.h"

namespace subdiv {

// A run of finished rows (CSR). Chunks of rows are large and live only until the step's
// table is assembled, so they take bulk memory, which is returned at once when freed.
struct RowBlock {
  BulkVector<Index> offsets{0};
  BulkVector<Index> indices;
  BulkVector<double> weights;
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
  RowBuilder() { slots_.fill(kEmpty); }
  void clear() {
    for (std::uint8_t slot : used_slots_) slots_[slot] = kEmpty;
    used_slots_.clear(), indices_.clear(), weights_.clear();
    if (!long_row_.empty()) long_row_.clear();
  }
  void add(Index source, double weight) {
    if (indices_.size() >= kMaxHashed) return add_beyond_table(source, weight);
    const size_t at = find_slot(source);
    std::int16_t& slot = slots_[at];
    if (slot != kEmpty) {
      weights_[slot] += weight;
      return;
    }
    slot = std::int16_t(indices_.size());
    used_slots_.push_back(std::uint8_t(at));
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
  static constexpr int kSlots = 128;  // power of two, well above kMaxHashed
  static constexpr size_t kMaxHashed = 48;
  static constexpr std::int16_t kEmpty = -1;

  // Linear probing; only the first kMaxHashed sources are in the table.
  size_t find_slot(Index source) const {
    size_t h = (std::uint32_t(source) * 2654435761u) >> 25;
    while (slots_[h] != kEmpty && indices_[slots_[h]] != source) h = (h + 1) & (kSlots - 1);
    return h;
  }
  // The first kMaxHashed sources are in the table, the rest in long_row_.
  void add_beyond_table(Index source, double weight) {
    const std::int16_t slot = slots_[find_slot(source)];
    if (slot != kEmpty) {
      weights_[size_t(slot)] += weight;
      return;
    }
    const auto [it, inserted] = long_row_.try_emplace(source, indices_.size());
    if (!inserted) {
      weights_[it->second] += weight;
      return;
    }
    indices_.push_back(source);
    weights_.push_back(weight);
  }

  std::array<std::int16_t, kSlots> slots_;
  std::vector<std::uint8_t> used_slots_;
  std::vector<Index> indices_;
  std::vector<double> weights_;
  std::unordered_map<Index, size_t> long_row_;
};

}  // namespace subdiv
