#include "framework/limit/step_matrix.h"

#include <algorithm>

#include <Eigen/Dense>

#include "framework/stencil/stencil_table.h"
#include "framework/util/error.h"

namespace subdiv {

namespace {

// A row's sums kept in registers for a known channel count (the caller's values are
// positions, 3): the same products added in the same order as the general loop.
template <size_t C>
void apply_rows(const StepMatrix& m, const double* in, double* out) {
  for (Index r = 0; r < m.rows(); ++r) {
    std::array<double, C> o{};
    for (Index e = m.offsets[size_t(r)]; e < m.offsets[size_t(r) + 1]; ++e) {
      const double w = m.weights[size_t(e)];
      const double* x = in + size_t(m.columns[size_t(e)]) * C;
      for (size_t c = 0; c < C; ++c) o[c] += w * x[c];
    }
    for (size_t c = 0; c < C; ++c) out[size_t(r) * C + c] = o[c];
  }
}

// Rows `scaled` (their entries times the step's scale) pulled through m into `next`, all
// rows in one pass over m's entries; each row's sums in the order a pass of its own takes.
template <size_t N>
void pull_through(const StepMatrix& m, double scale, const std::array<std::vector<double>*, 3>& rows,
                  std::array<std::vector<double>, 3>& next) {
  for (Index r = 0; r < m.rows(); ++r) {
    std::array<double, N> x;
    bool all = true, any = false;
    for (size_t k = 0; k < N; ++k) {
      x[k] = scale * (*rows[k])[size_t(r)];
      all = all && x[k] != 0, any = any || x[k] != 0;
    }
    if (!any) continue;
    const Index from = m.offsets[size_t(r)], to = m.offsets[size_t(r) + 1];
    if (all) {
      for (Index e = from; e < to; ++e) {
        const size_t col = size_t(m.columns[size_t(e)]);
        const double w = m.weights[size_t(e)];
        for (size_t k = 0; k < N; ++k) next[k][col] += x[k] * w;
      }
      continue;
    }
    for (size_t k = 0; k < N; ++k) {
      if (x[k] == 0) continue;
      for (Index e = from; e < to; ++e) next[k][size_t(m.columns[size_t(e)])] += x[k] * m.weights[size_t(e)];
    }
  }
}

}  // namespace

void StepMatrix::apply(std::span<const double> in, std::span<double> out, int channels) const {
  const size_t C = size_t(channels);
  if (C == 3) return apply_rows<3>(*this, in.data(), out.data());
  if (C == 1) return apply_rows<1>(*this, in.data(), out.data());
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

void pull_back_rows(std::span<std::vector<double>* const> rows, std::span<const StepMatrix* const> steps, int order) {
  const size_t n = rows.size();
  if (n == 0) return;
  if (n > 3) {
    for (std::vector<double>* row : rows) pull_back_rows({&row, 1}, steps, order);
    return;
  }
  std::array<std::vector<double>*, 3> at{};
  std::copy(rows.begin(), rows.end(), at.begin());
  // The rows after each step, swapped with the caller's: their room is kept from step to
  // step and from call to call.
  thread_local std::array<std::vector<double>, 3> next;
  for (size_t j = steps.size(); j-- > 0;) {
    const StepMatrix* form = order == 2 ? steps[j]->backward2 : steps[j]->backward;
    const StepMatrix& m = form ? *form : *steps[j];
    const double scale = order == 2 ? m.scale * m.scale : m.scale;
    for (size_t k = 0; k < n; ++k) next[k].assign(size_t(m.source_count), 0.0);
    if (n == 1) pull_through<1>(m, scale, at, next);
    if (n == 2) pull_through<2>(m, scale, at, next);
    if (n == 3) pull_through<3>(m, scale, at, next);
    for (size_t k = 0; k < n; ++k) {
      double sum = 0;
      int used = 0;
      for (double x : next[k]) sum += x, used += x != 0 ? 1 : 0;
      if (used > 0) {
        const double mean = sum / used;
        for (double& x : next[k])
          if (x != 0) x -= mean;
      }
      at[k]->swap(next[k]);
    }
  }
}

std::vector<double> pulled_back(std::vector<double> row, std::span<const StepMatrix* const> steps, int order) {
  std::vector<double>* rows[] = {&row};
  pull_back_rows(rows, steps, order);
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
  FirstDerivativeRows out;
  out.du.resize(ds.size()), out.dv.resize(ds.size());
  for (size_t i = 0; i < ds.size(); ++i) {
    out.du[i] = J[0][0] * ds[i] + J[1][0] * dt[i];
    out.dv[i] = J[0][1] * ds[i] + J[1][1] * dt[i];
  }
  std::vector<double>* rows[] = {&out.du, &out.dv};
  pull_back_rows(rows, steps, 1);
  return out;
}

SecondDerivativeRows second_derivative_rows(std::span<const double> dss, std::span<const double> dst,
                                            std::span<const double> dtt, const std::array<std::array<double, 2>, 2>& J,
                                            std::span<const StepMatrix* const> steps) {
  // Every step is affine, so the chain rule has no second-order term:
  // d2/du_a du_b = sum J[i][a] J[j][b] d2/ds_i ds_j.
  auto row = [&](size_t a, size_t b) {
    std::vector<double> r(dss.size());
    for (size_t i = 0; i < r.size(); ++i)
      r[i] = J[0][a] * J[0][b] * dss[i] + (J[0][a] * J[1][b] + J[1][a] * J[0][b]) * dst[i] + J[1][a] * J[1][b] * dtt[i];
    return r;
  };
  SecondDerivativeRows out{row(0, 0), row(0, 1), row(1, 1)};
  std::vector<double>* rows[] = {&out.duu, &out.duv, &out.dvv};
  pull_back_rows(rows, steps, 2);
  return out;
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

std::unique_ptr<StepPowers> lazy_step_powers(const StepMatrix& step, double factor, int count, const AffineFrame* frame) {
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
  if (frame) {
    // M Pi = (M 1) e_c0' + (M S)(e_c1 - e_c0)' + (M T)(e_c2 - e_c0)' (AffineFrame).
    Eigen::VectorXd S(k), T(k);
    for (Index v = 0; v < k; ++v) S(v) = frame->at[size_t(v)][0], T(v) = frame->at[size_t(v)][1];
    const Eigen::VectorXd one = s.m.rowwise().sum(), ms = s.m * S, mt = s.m * T;
    const auto [c0, c1, c2] = frame->corners;
    s.d2.col(c0) -= factor * factor * (one - ms - mt);
    s.d2.col(c1) -= factor * factor * ms;
    s.d2.col(c2) -= factor * factor * mt;
  } else {
    s.d2.col(0).array() -= factor * factor;
  }
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
