#include "framework/limit/step_matrix.h"

#include "framework/stencil/stencil_table.h"

namespace subdiv {

void StepMatrix::apply(std::span<const double> in, std::span<double> out, int channels) const {
  const size_t C = size_t(channels);
  for (Index r = 0; r < rows(); ++r) {
    double* o = out.data() + size_t(r) * C;
    for (size_t c = 0; c < C; ++c) o[c] = 0;
    for (Index e = offsets[size_t(r)]; e < offsets[size_t(r) + 1]; ++e) {
      const double w = weights[size_t(e)];
      const double* x = in.data() + size_t(columns[size_t(e)]) * C;
      for (size_t c = 0; c < C; ++c) o[c] += w * x[c];
    }
  }
}

std::vector<double> pulled_back(std::vector<double> row, std::span<const StepMatrix* const> steps, int order) {
  for (size_t j = steps.size(); j-- > 0;) {
    const StepMatrix* form = order == 2 ? steps[j]->backward2 : steps[j]->backward;
    const StepMatrix& m = form ? *form : *steps[j];
    const double scale = order == 2 ? m.scale * m.scale : m.scale;
    std::vector<double> next(size_t(m.source_count), 0.0);
    for (Index r = 0; r < m.rows(); ++r) {
      const double x = scale * row[size_t(r)];
      if (x == 0) continue;
      for (Index e = m.offsets[size_t(r)]; e < m.offsets[size_t(r) + 1]; ++e)
        next[size_t(m.columns[size_t(e)])] += x * m.weights[size_t(e)];
    }
    double sum = 0;
    int used = 0;
    for (double x : next) sum += x, used += x != 0 ? 1 : 0;
    if (used > 0)
      for (double& x : next)
        if (x != 0) x -= sum / used;
    row = std::move(next);
  }
  return row;
}

StepMatrix step_matrix(const StencilTable& table, const std::vector<Index>& rows, Index source_count) {
  StepMatrix m;
  m.source_count = source_count;
  for (Index r : rows) {
    for (Index e = table.offsets[size_t(r)]; e < table.offsets[size_t(r) + 1]; ++e) {
      m.columns.push_back(table.indices[size_t(e)]);
      m.weights.push_back(table.weights[size_t(e)]);
    }
    m.offsets.push_back(Index(m.columns.size()));
  }
  return m;
}

std::vector<double> applied(const std::vector<double>& row, std::span<const double> values, int channels) {
  std::vector<double> out(size_t(channels), 0.0);
  for (size_t v = 0; v < row.size(); ++v)
    if (row[v] != 0)
      for (int c = 0; c < channels; ++c) out[size_t(c)] += row[v] * values[v * size_t(channels) + size_t(c)];
  return out;
}

FirstDerivativeRows first_derivative_rows(std::span<const double> ds, std::span<const double> dt,
                                          const std::array<std::array<double, 2>, 2>& J,
                                          std::span<const StepMatrix* const> steps) {
  auto row = [&](size_t d) {
    std::vector<double> r(ds.size());
    for (size_t i = 0; i < r.size(); ++i) r[i] = J[0][d] * ds[i] + J[1][d] * dt[i];
    return pulled_back(std::move(r), steps);
  };
  return {row(0), row(1)};
}

}  // namespace subdiv
