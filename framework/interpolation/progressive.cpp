#include "framework/interpolation/progressive.h"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include "framework/util/error.h"
#include "framework/util/input_file.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

std::vector<std::uint8_t> all_or(std::span<const std::uint8_t> moving, Index count) {
  if (moving.empty()) return std::vector<std::uint8_t>(size_t(count), 1);
  if (moving.size() != size_t(count))
    throw Error(fmt::format("progressive interpolation: {} moving flags for {} vertices", moving.size(), count));
  return {moving.begin(), moving.end()};
}

void check_sizes(const StencilTable& limit, std::span<const double> targets, int channels) {
  if (channels < 1) throw Error("progressive interpolation: channels must be positive");
  if (limit.row_count() != limit.source_count)
    throw Error(fmt::format("progressive interpolation: the limit operator maps {} control points to {} limit "
                            "points; it must be square (one limit point per vertex)",
                            limit.source_count, limit.row_count()));
  if (targets.size() != size_t(limit.row_count()) * channels)
    throw Error(fmt::format("progressive interpolation: {} target values for {} vertices of {} channels",
                            targets.size(), limit.row_count(), channels));
  for (size_t i = 0; i < targets.size(); ++i)
    if (!std::isfinite(targets[i]))
      throw Error(fmt::format("progressive interpolation: target of vertex {} is not finite", i / channels));
}

}  // namespace

double default_interpolation_tolerance(std::span<const double> targets) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (size_t i = 0; i < targets.size(); ++i)
    lo[i % 3] = std::min(lo[i % 3], targets[i]), hi[i % 3] = std::max(hi[i % 3], targets[i]);
  double d2 = 0;
  for (int c = 0; c < 3; ++c) d2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
  return 1e-10 * std::max(std::sqrt(d2), 1e-300);
}

ProgressiveResult progressive_interpolation(const StencilTable& limit, std::span<const double> targets,
                                            std::span<const std::uint8_t> moving_flags,
                                            const ProgressiveOptions& options) {
  const int ch = options.channels;
  check_sizes(limit, targets, ch);
  const Index n = limit.row_count();
  const std::vector<std::uint8_t> moving = all_or(moving_flags, n);
  std::vector<Index> moving_ids;
  for (Index v = 0; v < n; ++v)
    if (moving[v]) moving_ids.push_back(v);
  if (moving_ids.empty()) throw Error("progressive interpolation: no vertex is selected to move");
  if (options.max_iterations < 0) throw Error("progressive interpolation: the iteration cap must be >= 0");

  ProgressiveResult r;
  r.control.assign(targets.begin(), targets.end());
  r.limit.assign(targets.size(), 0.0);
  std::vector<double> d(size_t(moving_ids.size()) * ch);
  for (int k = 0;; ++k) {
    limit.apply(r.control, r.limit, ch);
    IterationRecord rec;
    rec.iteration = k;
    double sum2 = 0;
    for (size_t i = 0; i < moving_ids.size(); ++i) {
      const size_t v = size_t(moving_ids[i]);
      double len2 = 0;
      for (int c = 0; c < ch; ++c) {
        const double x = targets[v * ch + c] - r.limit[v * ch + c];
        d[i * ch + c] = x;
        len2 += x * x;
      }
      sum2 += len2;
      rec.max_residual = std::max(rec.max_residual, std::sqrt(len2));
    }
    rec.rms_residual = std::sqrt(sum2 / double(moving_ids.size()));
    r.history.push_back(rec);
    if (options.observer) options.observer(IterationState{r.history.back(), r.control, r.limit});
    if (!std::isfinite(rec.max_residual) ||
        (k > 0 && rec.max_residual > 1e6 * std::max(r.history.front().max_residual, 1e-300)))
      throw Error(fmt::format("progressive interpolation diverges: the largest residual grew from {:.3e} to {:.3e} "
                              "in {} iterations (the limit operator on the moving vertices has eigenvalues outside "
                              "(0, 2))", r.history.front().max_residual, rec.max_residual, k));
    if (rec.max_residual <= options.tolerance) {
      r.converged = true;
      break;
    }
    if (k == options.max_iterations) break;
    for (size_t i = 0; i < moving_ids.size(); ++i)
      for (int c = 0; c < ch; ++c) r.control[size_t(moving_ids[i]) * ch + c] += d[i * ch + c];
    r.iterations = k + 1;
  }
  return r;
}

ProgressiveResult progressive_interpolation(const LimitEvaluator& evaluator, const Level& level,
                                            std::span<const double> targets, std::span<const std::uint8_t> moving,
                                            const ProgressiveOptions& options) {
  return progressive_interpolation(evaluator.limit_stencils(level), targets, moving, options);
}

std::vector<double> predicted_fixed_offsets(const StencilTable& limit, std::span<const double> targets,
                                            std::span<const std::uint8_t> moving_flags, int channels) {
  check_sizes(limit, targets, channels);
  const Index n = limit.row_count();
  const std::vector<std::uint8_t> moving = all_or(moving_flags, n);
  // Position of each vertex within P or Q.
  std::vector<Index> slot(n);
  Index p = 0, q = 0;
  for (Index v = 0; v < n; ++v) slot[v] = moving[v] ? p++ : q++;
  if (p == 0) throw Error("theorem 2: no vertex is selected to move");
  const std::vector<double> l0 = limit.apply(targets, channels);
  using Sparse = Eigen::SparseMatrix<double>;
  std::vector<Eigen::Triplet<double>> pp, qp;
  Eigen::MatrixXd dp(p, channels), dq(q, channels);
  for (Index v = 0; v < n; ++v) {
    for (Index i = limit.offsets[v]; i < limit.offsets[v + 1]; ++i) {
      const Index s = limit.indices[i];
      if (!moving[s]) continue;
      (moving[v] ? pp : qp).emplace_back(slot[v], slot[s], limit.weights[i]);
    }
    for (int c = 0; c < channels; ++c) {
      const double d0 = targets[size_t(v) * channels + c] - l0[size_t(v) * channels + c];
      (moving[v] ? dp : dq)(slot[v], c) = d0;
    }
  }
  Sparse m(p, p), e(q, p);
  m.setFromTriplets(pp.begin(), pp.end());
  e.setFromTriplets(qp.begin(), qp.end());
  Eigen::SparseLU<Sparse> lu;
  lu.compute(m);
  if (lu.info() != Eigen::Success)
    throw Error("theorem 2: the limit operator restricted to the moving vertices (M = L_PP) is singular");
  const Eigen::MatrixXd x = lu.solve(dp);
  const Eigen::MatrixXd dq_inf = dq - e * x;
  std::vector<double> out(size_t(n) * channels, 0.0);
  for (Index v = 0; v < n; ++v)
    if (!moving[v])
      for (int c = 0; c < channels; ++c) out[size_t(v) * channels + c] = dq_inf(slot[v], c);
  return out;
}

std::vector<std::uint8_t> parse_vertex_selection(const std::string& text, Index vertex_count,
                                                 const std::string& source) {
  std::vector<std::string> tokens;
  int line = 1;
  std::vector<int> lines;
  std::string cur;
  bool comment = false;
  auto flush = [&] {
    if (!cur.empty()) tokens.push_back(cur), lines.push_back(line), cur.clear();
  };
  for (char c : without_utf8_bom(text)) {
    if (c == '\n') {
      flush();
      comment = false;
      ++line;
    } else if (comment) {
    } else if (c == '#') {
      flush();
      comment = true;
    } else if (c == ',' || c == ' ' || c == '\t' || c == '\r') {
      flush();
    } else {
      cur += c;
    }
  }
  flush();
  std::vector<std::uint8_t> moving(size_t(vertex_count), 0);
  if (tokens.size() == 1 && (tokens[0] == "all" || tokens[0] == "ALL")) {
    std::fill(moving.begin(), moving.end(), 1);
    return moving;
  }
  if (tokens.empty()) throw Error(fmt::format("{}: the selection names no vertices; give 0-based ids or 'all'", source));
  const bool multiline = line > 1;
  for (size_t i = 0; i < tokens.size(); ++i) {
    const std::string where = multiline ? fmt::format("{} line {}", source, lines[i]) : source;
    const std::string& t = tokens[i];
    long long id = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), id);
    if (ec != std::errc() || end != t.data() + t.size())
      throw Error(fmt::format("{}: {} is not a vertex id; give 0-based ids separated by commas, or 'all'", where, subdiv::quoted(t)));
    if (id < 0 || id >= vertex_count)
      throw Error(fmt::format("{}: vertex {} does not exist; the mesh has {} vertices (ids 0 to {})", where, id,
                              vertex_count, vertex_count - 1));
    moving[size_t(id)] = 1;
  }
  return moving;
}

}  // namespace subdiv
