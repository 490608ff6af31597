#include "framework/stencil/stencil_table.h"

#include <algorithm>
#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/util/bulk_memory.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// Rows per parallel task: large enough to amortise scheduling, small enough to balance.
constexpr Index kGrain = 2048;

// Which row goes to output place k: every row in order (apply), or the caller's list
// (apply_rows). A type rather than a null pointer, so that apply's loop has no test in it.
struct AllRows {
  Index operator()(Index k) const { return k; }
};
struct ChosenRows {
  const Index* rows;
  Index operator()(Index k) const { return rows[k]; }
};

// Rows row_of(begin..end) into dst's places begin..end. The arrays as raw pointers: the
// output cannot alias them, but through the vectors the compiler would reload their data
// pointers after every store.
template <int Channels, class RowOf>
void sum_rows(const StencilTable& t, const double* __restrict src, double* __restrict dst, Index begin, Index end,
              RowOf row_of) {
  const Index* __restrict offsets = t.offsets.data();
  const Index* __restrict indices = t.indices.data();
  const double* __restrict weights = t.weights.data();
  for (Index k = begin; k < end; ++k) {
    const Index r = row_of(k);
    double sum[Channels] = {};
    for (Index i = offsets[r]; i < offsets[r + 1]; ++i) {
      const double w = weights[i];
      const double* s = src + size_t(indices[i]) * Channels;
      for (int c = 0; c < Channels; ++c) sum[c] += w * s[c];
    }
    std::copy(sum, sum + Channels, dst + size_t(k) * Channels);
  }
}

template <class RowOf>
void sum_rows_any(const StencilTable& t, const double* src, double* dst, int channels, Index begin, Index end,
                  RowOf row_of) {
  for (Index k = begin; k < end; ++k) {
    const Index r = row_of(k);
    double* out = dst + size_t(k) * channels;
    std::fill(out, out + channels, 0.0);
    for (Index i = t.offsets[r]; i < t.offsets[r + 1]; ++i) {
      const double w = t.weights[i];
      const double* s = src + size_t(t.indices[i]) * channels;
      for (int c = 0; c < channels; ++c) out[c] += w * s[c];
    }
  }
}

// `count` output places in parallel, each row summed in its stored order (the same bits for
// any thread count).
template <class RowOf>
void sum_all(const StencilTable& t, const double* src, double* dst, int channels, Index count, RowOf row_of) {
  tbb::parallel_for(tbb::blocked_range<Index>(0, count, kGrain), [&](const auto& range) {
    switch (channels) {
      case 1: sum_rows<1>(t, src, dst, range.begin(), range.end(), row_of); break;
      case 3: sum_rows<3>(t, src, dst, range.begin(), range.end(), row_of); break;
      default: sum_rows_any(t, src, dst, channels, range.begin(), range.end(), row_of);
    }
  });
}

}  // namespace

void StencilTable::apply(std::span<const double> src, std::span<double> dst, int channels) const {
  if (src.size() < size_t(source_count) * channels || dst.size() < size_t(row_count()) * channels)
    throw Error(fmt::format("stencil apply: buffers of {} and {} values are too small for {} "
                            "sources and {} rows of {} channels",
                            src.size(), dst.size(), source_count, row_count(), channels));
  sum_all(*this, src.data(), dst.data(), channels, row_count(), AllRows{});
}

std::vector<double> StencilTable::apply_rows(std::span<const double> src, std::span<const Index> rows,
                                             int channels) const {
  if (src.size() < size_t(source_count) * channels)
    throw Error(fmt::format("stencil apply: {} values are too few for {} sources of {} channels", src.size(),
                            source_count, channels));
  for (Index r : rows)
    if (r < 0 || r >= row_count()) throw Error(fmt::format("stencil apply: row {} is not in 0..{}", r, row_count() - 1));
  std::vector<double> dst(rows.size() * size_t(channels));
  sum_all(*this, src.data(), dst.data(), channels, Index(rows.size()), ChosenRows{rows.data()});
  return dst;
}

std::vector<double> StencilTable::apply(std::span<const double> src, int channels) const {
  std::vector<double> dst;
  resize_bulk(dst, size_t(row_count()) * channels);
  apply(src, dst, channels);
  return dst;
}

StencilTable compose(const StencilTable& first, const StencilTable& second) {
  if (second.source_count != first.row_count())
    throw Error(fmt::format("cannot compose stencil tables: the second reads {} values but the "
                            "first makes {}", second.source_count, first.row_count()));
  StencilTable out;
  out.source_count = first.source_count;
  out.offsets.assign(second.row_count() + 1, 0);
  // Dense scratch row with a touched list keeps each row's merge linear in its size.
  std::vector<double> acc(first.source_count, 0.0);
  std::vector<char> seen(first.source_count, 0);
  std::vector<Index> touched;
  for (Index r = 0; r < second.row_count(); ++r) {
    touched.clear();
    for (Index i = second.offsets[r]; i < second.offsets[r + 1]; ++i) {
      const Index mid = second.indices[i];
      const double w = second.weights[i];
      for (Index j = first.offsets[mid]; j < first.offsets[mid + 1]; ++j) {
        const Index s = first.indices[j];
        if (!seen[s]) seen[s] = 1, touched.push_back(s);
        acc[s] += w * first.weights[j];
      }
    }
    std::sort(touched.begin(), touched.end());
    for (Index s : touched) {
      out.indices.push_back(s);
      out.weights.push_back(acc[s]);
      acc[s] = 0.0, seen[s] = 0;
    }
    out.offsets[r + 1] = Index(out.indices.size());
  }
  return out;
}

}  // namespace subdiv
