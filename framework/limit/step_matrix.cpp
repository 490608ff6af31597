#include "framework/limit/step_matrix.h"

#include <algorithm>

#include <Eigen/Dense>

#include "framework/stencil/stencil_table.h"
#include "framework/util/error.h"

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

namespace {

StepMatrix sparse_step(const Eigen::MatrixXd& a) {
  StepMatrix m;
  m.source_count = Index(a.cols());
  m.scale = 1;
  for (Index r = 0; r < Index(a.rows()); ++r) {
    for (Index c = 0; c < Index(a.cols()); ++c)
      if (a(r, c) != 0) m.columns.push_back(c), m.weights.push_back(a(r, c));
    m.offsets.push_back(Index(m.columns.size()));
  }
  return m;
}

}  // namespace

struct StepPowers::Squares {
  Eigen::MatrixXd m, d;  // M^(2^j) and (factor (M - 1 e_0))^(2^j), j the powers made
  Eigen::MatrixXd d2;    // (factor^2 (M - 1 e_0))^(2^j), j the second-derivative forms made
  int capacity = 0;
};

StepPowers::StepPowers() = default;
StepPowers::~StepPowers() = default;

std::unique_ptr<StepPowers> lazy_step_powers(const StepMatrix& step, double factor, int count) {
  const Index k = step.rows();
  if (k != step.source_count) throw Error("internal: a self-similar step is not square");
  auto p = std::make_unique<StepPowers>();
  p->next = std::make_unique<StepPowers::Squares>();
  StepPowers::Squares& s = *p->next;
  s.capacity = count;
  s.m = Eigen::MatrixXd::Zero(k, k);
  for (Index r = 0; r < k; ++r)
    for (Index e = step.offsets[size_t(r)]; e < step.offsets[size_t(r) + 1]; ++e)
      s.m(r, step.columns[size_t(e)]) += step.weights[size_t(e)];
  s.d = factor * s.m;
  s.d.col(0).array() -= factor;
  s.d2 = factor * factor * s.m;
  s.d2.col(0).array() -= factor * factor;
  p->forward.reserve(size_t(count));
  p->backward.reserve(size_t(count));
  p->backward2.reserve(size_t(count));
  return p;
}

void more_powers(StepPowers& p, int count, bool second) {
  if (!p.next) return;  // every power and form made
  StepPowers::Squares& s = *p.next;
  count = std::min(count, s.capacity);
  while (int(p.forward.size()) < count) {
    p.forward.push_back(sparse_step(s.m));
    p.backward.push_back(sparse_step(s.d));
    p.forward.back().backward = &p.backward.back();
    s.m = (s.m * s.m).eval();
    s.d = (s.d * s.d).eval();
  }
  if (!second) return;
  while (p.backward2.size() < p.forward.size()) {
    p.backward2.push_back(sparse_step(s.d2));
    p.forward[p.backward2.size() - 1].backward2 = &p.backward2.back();
    s.d2 = (s.d2 * s.d2).eval();
  }
  // The dense squares (three matrices of the step's size squared) are not needed any more.
  if (int(p.backward2.size()) == s.capacity) p.next.reset();
}

std::unique_ptr<StepPowers> step_powers(const StepMatrix& step, double factor, int count, bool second) {
  auto p = lazy_step_powers(step, factor, count);
  more_powers(*p, count, second);
  p->next.reset();  // all made
  return p;
}

}  // namespace subdiv
