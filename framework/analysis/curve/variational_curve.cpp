#include "framework/analysis/curve/variational_curve.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "framework/rules/formula.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

// Weights below this share of a row's largest are round-off: trimmed from rules.
constexpr double kTrim = 1e-17;

// The refined polygon of n old points: its size, and where each refined point goes — old
// point f / m, or unknown u (the new points in order).
struct Refined {
  long size = 0;
  bool closed = false;
  int m = 2;
  bool is_old(long f) const { return f % m == 0; }
  long old_index(long f) const { return f / m; }
  long unknown(long f) const { return (f / m) * (m - 1) + f % m - 1; }
};

// The energy's matrix M (E = |M P|^2) split into the columns of the unknowns and of the old
// points: rows are the i whose stencil lies inside (open) or all i (closed, indices cyclic).
void energy_matrices(const VariationalEnergy& e, const Refined& p, long n, long unknowns, Sparse& on_new,
                     Sparse& on_old) {
  const long s = long(e.alpha.size()) - 1;
  std::vector<Eigen::Triplet<double>> new_terms, old_terms;
  long rows = 0;
  for (long i = 0; i < p.size; ++i) {
    const long first = i - e.r;
    if (!p.closed && (first < 0 || first + s >= p.size)) continue;
    for (long j = 0; j <= s; ++j) {
      if (e.alpha[size_t(j)] == 0.0) continue;
      const long f = p.closed ? ((first + j) % p.size + p.size) % p.size : first + j;
      if (p.is_old(f)) old_terms.emplace_back(rows, p.old_index(f), e.alpha[size_t(j)]);
      else new_terms.emplace_back(rows, p.unknown(f), e.alpha[size_t(j)]);
    }
    ++rows;
  }
  on_new.resize(rows, unknowns);
  on_old.resize(rows, n);
  on_new.setFromTriplets(new_terms.begin(), new_terms.end());  // repeated entries (short cycles) add up
  on_old.setFromTriplets(old_terms.begin(), old_terms.end());
}

// The normal equations (M_new^T M_new) x = -(M_new^T M_old) p, solved for every old point's
// unit vector at once: column c of the result is the new points' weights on old point c.
Eigen::MatrixXd solve_whole(const VariationalEnergy& e, long n, bool closed) {
  Refined p{closed ? e.arity * n : e.arity * (n - 1) + 1, closed, e.arity};
  const long unknowns = (e.arity - 1) * (closed ? n : n - 1);
  if (unknowns <= 0) return Eigen::MatrixXd(0, n);
  Sparse on_new, on_old;
  energy_matrices(e, p, n, unknowns, on_new, on_old);
  const Sparse a = Sparse(on_new.transpose()) * on_new;
  const Eigen::MatrixXd b = -(Eigen::MatrixXd(Sparse(on_new.transpose()) * on_old));
  Eigen::SimplicialLDLT<Sparse> ldlt(a);
  const auto d = ldlt.vectorD();
  const double largest = d.size() ? d.cwiseAbs().maxCoeff() : 0.0;
  if (ldlt.info() != Eigen::Success || d.size() == 0 || d.minCoeff() <= 1e-12 * largest)
    throw Error(fmt::format("{}: the variational energy does not determine the new points of {} polyline of {} "
                            "points (each new point must be read by some K(P_i) whose points lie inside it); "
                            "give the polyline more points",
                            e.where, closed ? "a closed" : "an open", n));
  return ldlt.solve(b);
}

// Rule r of the bi-infinite scheme from a closed polygon of kVariationalWindow points: the
// new points after old point c = window/2, their weights on old points c + offset.
std::vector<std::vector<double>> middle_rows(const VariationalEnergy& e, std::vector<long>& first_offset) {
  const long n = kVariationalWindow, c = n / 2;
  const Eigen::MatrixXd x = solve_whole(e, n, true);
  std::vector<std::vector<double>> rules;
  first_offset.clear();
  for (int r = 1; r < e.arity; ++r) {
    const long q = c * (e.arity - 1) + r - 1;
    const double largest = x.row(q).cwiseAbs().maxCoeff();
    long lo = 0, hi = n - 1;
    while (lo < hi && std::abs(x(q, lo)) <= kTrim * largest) ++lo;
    while (hi > lo && std::abs(x(q, hi)) <= kTrim * largest) --hi;
    if (lo == 0 || hi == n - 1)
      throw Error(fmt::format("{}: the variational scheme's weights do not decay to round-off within {} old points; "
                              "its energy is too close to singular for a stationary rule",
                              e.where, n / 2));
    std::vector<double> w;
    for (long k = lo; k <= hi; ++k) w.push_back(std::abs(x(q, k)) <= kTrim * largest ? 0.0 : x(q, k));
    rules.push_back(std::move(w));
    first_offset.push_back(lo - c);
  }
  return rules;
}

}  // namespace

VariationalEnergy variational_energy(const CurveScheme& curve, int level) {
  VariationalEnergy e;
  e.arity = curve.arity;
  e.r = curve.variational_r;
  e.where = curve.path;
  FormulaSet formulas(curve.parameters, curve.definitions);
  double sum = 0, magnitude = 0;
  for (size_t j = 0; j < curve.variational_alpha.size(); ++j) {
    const std::string place = fmt::format("{}: variational.alpha[{}]", curve.path, j);
    const double a = formulas.evaluate(formulas.add(curve.variational_alpha[j], place), {0, 0, double(j), double(level)});
    if (!std::isfinite(a)) throw Error(fmt::format("{}: {} is {} at level {}", place, subdiv::quoted(curve.variational_alpha[j]), a, level));
    e.alpha.push_back(a);
    sum += a, magnitude += std::abs(a);
  }
  if (magnitude == 0.0 || std::abs(sum) > 1e-12 * magnitude)
    throw Error(fmt::format("{}: variational.alpha: the coefficients sum to {} at level {}; K must vanish on "
                            "constant polygons (alpha(1) = 0), and not all may be 0",
                            curve.path, sum, level));
  return e;
}

std::vector<VariationalRow> variational_rows(const VariationalEnergy& e, long n, bool closed) {
  const long m = e.arity, per = m - 1;
  const long count = per * (closed ? n : n - 1);
  std::vector<VariationalRow> rows(size_t(std::max(count, 0L)));
  if (count <= 0) return rows;
  // Column k of row q of a solved window, kept where it is not round-off (all when `all`).
  auto copy_row = [](const Eigen::MatrixXd& x, long q, long shift, bool all, VariationalRow& row) {
    const double largest = x.row(q).cwiseAbs().maxCoeff();
    row.clear();
    for (long k = 0; k < x.cols(); ++k)
      if (x(q, k) != 0.0 && (all || std::abs(x(q, k)) > kTrim * largest)) row.emplace_back(k + shift, x(q, k));
  };
  if (n <= kVariationalWindow) {
    const Eigen::MatrixXd x = solve_whole(e, n, closed);
    for (long q = 0; q < count; ++q) copy_row(x, q, 0, true, rows[size_t(q)]);
    return rows;
  }
  // Long polylines: the bi-infinite rules away from the ends (exact to round-off, as the
  // weights decay geometrically), and an open polyline's first and last half windows from
  // a window-long open polyline.
  std::vector<long> first;
  const std::vector<std::vector<double>> rules = middle_rows(e, first);
  for (long i = 0; i < (closed ? n : n - 1); ++i)
    for (long r = 1; r < m; ++r) {
      VariationalRow& row = rows[size_t(i * per + r - 1)];
      const auto& w = rules[size_t(r - 1)];
      for (size_t t = 0; t < w.size(); ++t) {
        long k = i + first[size_t(r - 1)] + long(t);
        if (closed) k = ((k % n) + n) % n;
        else if (k < 0 || k >= n) continue;  // near an end: replaced below
        if (w[t] != 0.0) row.emplace_back(k, w[t]);
      }
      std::sort(row.begin(), row.end());
    }
  if (!closed) {
    const long w = kVariationalWindow, half = w / 2;
    const Eigen::MatrixXd x = solve_whole(e, w, false);
    for (long i = 0; i < half; ++i)
      for (long r = 1; r < m; ++r) {
        copy_row(x, i * per + r - 1, 0, false, rows[size_t(i * per + r - 1)]);
        copy_row(x, (w - 2 - i) * per + r - 1, n - w, false, rows[size_t((n - 2 - i) * per + r - 1)]);
      }
  }
  return rows;
}

void variational_rules(const VariationalEnergy& e, std::vector<int>& starts, std::vector<std::vector<double>>& weights) {
  std::vector<long> first;
  std::vector<std::vector<double>> rules = middle_rows(e, first);
  starts = {0};
  weights = {{1.0}};
  for (size_t r = 0; r < rules.size(); ++r) {
    starts.push_back(int(first[r]));
    weights.push_back(std::move(rules[r]));
  }
}

}  // namespace subdiv
