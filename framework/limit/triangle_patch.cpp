#include "framework/limit/triangle_patch.h"

#include <algorithm>
#include <array>
#include <utility>

namespace subdiv {
namespace {

constexpr int kDegree = 4;

// The lattice's points (i, j), i + j <= 4, in index order.
constexpr std::array<std::array<int, 2>, kQuarticLattice> lattice() {
  std::array<std::array<int, 2>, kQuarticLattice> out{};
  int q = 0;
  for (int j = 0; j <= kDegree; ++j)
    for (int i = 0; i + j <= kDegree; ++i) out[size_t(q++)] = {i, j};
  return out;
}

}  // namespace

void lagrange_factor(int m, double z, double& value, double& derivative, double& second) {
  value = 1, derivative = 0, second = 0;
  for (int a = 0; a < m; ++a) {
    const double f = (z - a) / (m - a), df = 1.0 / (m - a);
    second = second * f + 2 * derivative * df;
    derivative = derivative * f + value * df;
    value *= f;
  }
}

Uv quartic_lattice_point(int q) {
  const auto p = lattice()[size_t(q)];
  return {double(p[0]) / kDegree, double(p[1]) / kDegree};
}

namespace {

// The lattice's points (i, j, k = 4 - i - j) in index order.
constexpr std::array<std::array<int, 3>, kQuarticLattice> kPoints = [] {
  std::array<std::array<int, 3>, kQuarticLattice> out{};
  const auto points = lattice();
  for (size_t q = 0; q < size_t(kQuarticLattice); ++q)
    out[q] = {points[q][0], points[q][1], kDegree - points[q][0] - points[q][1]};
  return out;
}();

// The Lagrange factors l_m(z), m = 0..4, with their first and second derivatives in z (as
// many as the first `Count` rows need), by l_m = l_{m-1} (z - m + 1) / m, the division a
// product with 1 / m: a point costs a few products and no division. Still exact at the
// lattice: l_m(a) = 0 for integers a < m, and l_m(m) = 1 (the one inexact factor, 1 / 3.0,
// still gives 3 (1 / 3.0) = 1 and 12 (1 / 3.0) = 4 once rounded), so a lattice point's
// weights are its own row's exactly.
template <int Count>
struct Factors {
  std::array<double, kDegree + 1> value{}, first{}, second{};
  explicit Factors(double z) {
    constexpr double kInverse[] = {0, 1, 1.0 / 2, 1.0 / 3, 1.0 / 4};
    value[0] = 1;
    for (size_t m = 1; m <= size_t(kDegree); ++m) {
      const double f = z - double(m - 1), r = kInverse[m];
      if constexpr (Count >= 6) second[m] = (second[m - 1] * f + 2 * first[m - 1]) * r;
      if constexpr (Count >= 3) first[m] = (first[m - 1] * f + value[m - 1]) * r;
      value[m] = value[m - 1] * f * r;
    }
  }
};

// The lattice point q's Lagrange weight and its derivatives in (s, t): position, d/ds, d/dt,
// d2/ds2, d2/dsdt, d2/dt2 (the first `Count`), from the factors of z1 = 4 s, z2 = 4 t,
// z0 = 4 - z1 - z2 (the chain rule in barycentric coordinates).
template <int Count>
std::array<double, 6> lattice_weight(size_t q, const Factors<Count>& f1, const Factors<Count>& f2,
                                     const Factors<Count>& f0) {
  const size_t i = size_t(kPoints[q][0]), j = size_t(kPoints[q][1]), k = size_t(kPoints[q][2]);
  const double a = f1.value[i], b = f2.value[j], c = f0.value[k];
  const double d = kDegree, dd = d * d;
  std::array<double, 6> w{};
  w[0] = a * b * c;
  if constexpr (Count >= 3) {
    const double da = f1.first[i], db = f2.first[j], dc = f0.first[k];
    w[1] = d * (da * b * c - a * b * dc);
    w[2] = d * (a * db * c - a * b * dc);
    if constexpr (Count >= 6) {
      const double dda = f1.second[i], ddb = f2.second[j], ddc = f0.second[k];
      w[3] = dd * (dda * b * c - 2 * da * b * dc + a * b * ddc);
      w[4] = dd * (da * db * c - da * b * dc - a * db * dc + a * b * ddc);
      w[5] = dd * (a * ddb * c - 2 * a * db * dc + a * b * ddc);
    }
  }
  return w;
}

int row_count(int order) { return order >= 2 ? 6 : order == 1 ? 3 : 1; }

// The fifteen lattice weights at (s, t).
template <int Count>
std::array<std::array<double, 6>, kQuarticLattice> weights(const Uv& st) {
  const double z1 = kDegree * st[0], z2 = kDegree * st[1], z0 = kDegree - z1 - z2;
  const Factors<Count> f1(z1), f2(z2), f0(z0);
  std::array<std::array<double, 6>, kQuarticLattice> w{};
  for (size_t q = 0; q < size_t(kQuarticLattice); ++q) w[q] = lattice_weight<Count>(q, f1, f2, f0);
  return w;
}

// out[n][l] = the sum over the lattice points q, in order, of weight_q[n] row_q[l], for
// `Count` rows n, each sum from +0 without skipping zeros (a zero product leaves such a sum
// as it was, so the bits are those of skipping it; the loops are free of branches). With the
// number of labels L known at compile time the sums stay in registers; every L gives each
// entry the same operations in the same order, so the bits do not depend on which loop ran.
template <int Count, size_t L>
void accumulate_fixed(const std::vector<std::vector<double>>& rows, const Uv& st, double* const* out) {
  const auto w = weights<Count>(st);
  std::array<std::array<double, L>, size_t(Count)> sum{};
  for (size_t q = 0; q < size_t(kQuarticLattice); ++q) {
    const double* row = rows[q].data();
    for (size_t n = 0; n < size_t(Count); ++n)
      for (size_t l = 0; l < L; ++l) sum[n][l] += w[q][n] * row[l];
  }
  for (size_t n = 0; n < size_t(Count); ++n) std::copy(sum[n].begin(), sum[n].end(), out[n]);
}

template <int Count>
void accumulate_any(const std::vector<std::vector<double>>& rows, const Uv& st, double* const* out) {
  const size_t labels = rows.front().size();
  const auto w = weights<Count>(st);
  for (size_t n = 0; n < size_t(Count); ++n) std::fill(out[n], out[n] + labels, 0.0);
  for (size_t q = 0; q < size_t(kQuarticLattice); ++q) {
    const double* row = rows[q].data();
    for (size_t n = 0; n < size_t(Count); ++n) {
      double* o = out[n];
      const double x = w[q][n];
      for (size_t l = 0; l < labels; ++l) o[l] += x * row[l];
    }
  }
}

// accumulate_fixed for each L up to kFixedLabels, else accumulate_any.
template <int Count, size_t... L>
void accumulate_by_size(const std::vector<std::vector<double>>& rows, const Uv& st, double* const* out,
                        std::index_sequence<L...>) {
  using Kernel = void (*)(const std::vector<std::vector<double>>&, const Uv&, double* const*);
  static constexpr Kernel kernels[] = {&accumulate_fixed<Count, L + 1>...};
  const size_t labels = rows.front().size();
  if (labels >= 1 && labels <= sizeof...(L)) return kernels[labels - 1](rows, st, out);
  accumulate_any<Count>(rows, st, out);
}

void accumulate(const std::vector<std::vector<double>>& rows, const Uv& st, int count, double* const* out) {
  constexpr auto sizes = std::make_index_sequence<kFixedLabels>();
  if (count == 1) return accumulate_by_size<1>(rows, st, out, sizes);
  if (count == 3) return accumulate_by_size<3>(rows, st, out, sizes);
  accumulate_by_size<6>(rows, st, out, sizes);
}

// The rows from the patch's closed form or its lattice.
void patch_rows(const PolynomialPatch& patch, const Uv& st, int count, double* const* out) {
  if (patch.box) return box_spline_rows(*patch.box, st, count, out);
  accumulate(patch.lattice, st, count, out);
}

// Rows of `labels` entries sized for `order`, filled by `fill(count, out)`.
template <class Fill>
CornerRows rows_of(size_t labels, int order, Fill&& fill) {
  CornerRows r;
  // Position; then d/ds, d/dt; then the second derivatives.
  const int count = row_count(order);
  std::vector<double>* all[6] = {&r.position, &r.ds, &r.dt, &r.dss, &r.dst, &r.dtt};
  double* out[6] = {};
  for (int n = 0; n < count; ++n) all[n]->assign(labels, 0.0), out[n] = all[n]->data();
  fill(count, out);
  return r;
}

}  // namespace

PolynomialPatch triangle_patch(std::vector<std::vector<double>> lattice) {
  PolynomialPatch p;
  if (lattice.empty()) return p;
  p.box = box_spline_labels(lattice);
  p.lattice = std::move(lattice);
  return p;
}

CornerRows quartic_rows(const PolynomialPatch& patch, const Uv& st, int order) {
  return rows_of(patch.lattice.front().size(), order,
                 [&](int count, double* const* out) { patch_rows(patch, st, count, out); });
}

CornerRows quartic_rows(const std::vector<std::vector<double>>& rows, const Uv& st, int order) {
  return rows_of(rows.front().size(), order, [&](int count, double* const* out) { accumulate(rows, st, count, out); });
}

bool quartic_rows_fixed(const PolynomialPatch& patch, const Uv& st, int order, FixedRows& r) {
  r.labels = patch.lattice.front().size();
  if (r.labels > kFixedLabels) return false;
  r.count = row_count(order);
  // Every entry of the rows asked for is written (accumulate_fixed, box_spline_rows).
  double* out[6] = {};
  for (int n = 0; n < r.count; ++n) out[n] = r.row[size_t(n)].data();
  patch_rows(patch, st, r.count, out);
  return true;
}

}  // namespace subdiv
