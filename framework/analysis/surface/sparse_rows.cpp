#include "framework/analysis/surface/sparse_rows.h"

#include <algorithm>

namespace subdiv {

void normalise_row(SparseRow& row) {
  std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  size_t out = 0;
  for (size_t i = 0; i < row.size(); ++i) {
    if (out > 0 && row[out - 1].first == row[i].first) row[out - 1].second += row[i].second;
    else row[out++] = row[i];
  }
  row.resize(out);
}

SparseRow pull_back(const SparseRow& row, const StencilTable& step) {
  SparseRow out;
  for (const auto& [child, weight] : row)
    for (Index e = step.offsets[size_t(child)]; e < step.offsets[size_t(child) + 1]; ++e)
      out.emplace_back(step.indices[size_t(e)], weight * step.weights[size_t(e)]);
  normalise_row(out);
  return out;
}

SparseRow renumber(const SparseRow& row, const std::vector<Index>& original) {
  SparseRow out;
  out.reserve(row.size());
  for (const auto& [v, w] : row) out.emplace_back(original[size_t(v)], w);
  normalise_row(out);
  return out;
}

void apply_row(const SparseRow& row, std::span<const double> points, int channels, std::span<double> out) {
  std::fill(out.begin(), out.end(), 0.0);
  for (const auto& [v, w] : row)
    for (int c = 0; c < channels; ++c) out[size_t(c)] += w * points[size_t(v) * size_t(channels) + size_t(c)];
}

}  // namespace subdiv
