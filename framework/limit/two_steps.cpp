#include "framework/limit/two_steps.h"

#include <algorithm>

#include "framework/engine/refiner.h"

namespace subdiv {

StepMatrix two_step_matrix(const Hierarchy& h, const std::vector<Index>& rows, Index source_count, int scale) {
  StepMatrix m;
  m.source_count = source_count;
  m.scale = scale;
  const StencilTable& first = h.stencils[0];
  const StencilTable& second = h.stencils[1];
  std::vector<double> acc(size_t(source_count), 0.0);
  std::vector<char> used(size_t(source_count), 0);
  std::vector<Index> touched;
  for (Index r : rows) {
    for (Index e = second.offsets[size_t(r)]; e < second.offsets[size_t(r) + 1]; ++e) {
      const Index mid = second.indices[size_t(e)];
      const double w = second.weights[size_t(e)];
      for (Index x = first.offsets[size_t(mid)]; x < first.offsets[size_t(mid) + 1]; ++x) {
        const Index c = first.indices[size_t(x)];
        if (!used[size_t(c)]) used[size_t(c)] = 1, touched.push_back(c);
        acc[size_t(c)] += w * first.weights[size_t(x)];
      }
    }
    // Columns in increasing order, whatever order the stencils visit them in.
    std::sort(touched.begin(), touched.end());
    for (Index c : touched) {
      if (acc[size_t(c)] != 0) m.columns.push_back(c), m.weights.push_back(acc[size_t(c)]);
      acc[size_t(c)] = 0, used[size_t(c)] = 0;
    }
    touched.clear();
    m.offsets.push_back(Index(m.columns.size()));
  }
  return m;
}

}  // namespace subdiv
