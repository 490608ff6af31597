#pragma once
// A new point's weighted sum, for the kernels (smooth_kernels.h, flat_kernels.h): over C
// channels in registers (so the compiler need not assume that the output aliases the points
// it reads), or over any number of channels straight in the output (C = 0).
#include <algorithm>

#include "framework/util/streaming_stores.h"

namespace subdiv {

template <int C>
class PointAccumulator {
public:
  PointAccumulator(double* out, int) : out_(out) {}
  void add(const double* p, double w) {
    for (int c = 0; c < C; ++c) sum_[c] += w * p[c];
  }
  void store() const {
    for (int c = 0; c < C; ++c) out_[c] = sum_[c];
  }
  // The same values through streaming (non-temporal) stores: past the caches, without
  // reading each line in first. For output that nothing reads soon (a refinement's last
  // level, larger than the caches); streaming_fence() after the loop.
  void stream() const {
    for (int c = 0; c < C; ++c) stream_store(out_ + c, sum_[c]);
  }

private:
  double* out_;
  double sum_[C] = {};
};

template <>
class PointAccumulator<0> {
public:
  PointAccumulator(double* out, int channels) : out_(out), channels_(channels) { std::fill(out, out + channels, 0.0); }
  void add(const double* p, double w) {
    for (int c = 0; c < channels_; ++c) out_[c] += w * p[c];
  }
  void store() const {}
  void stream() const {}

private:
  double* out_;
  int channels_;
};

}  // namespace subdiv
