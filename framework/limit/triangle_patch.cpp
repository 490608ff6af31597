#include "framework/limit/triangle_patch.h"

#include <algorithm>
#include <array>

namespace subdiv {
namespace {

constexpr int kDegree = 4;

// The lattice's points (i, j), i + j <= 4, in index order.
std::array<std::array<int, 2>, kQuarticLattice> lattice() {
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

// The Lagrange factors l_m(z) of one barycentric coordinate for m = 0..4: value, first and
// second derivative. Each lattice weight is a product of three of them; a point's fifteen
// factors are computed once rather than per lattice point (the same values).
using Factors = std::array<std::array<double, 3>, kDegree + 1>;
Factors factors(double z) {
  Factors f{};
  for (int m = 0; m <= kDegree; ++m) lagrange_factor(m, z, f[size_t(m)][0], f[size_t(m)][1], f[size_t(m)][2]);
  return f;
}

// The lattice point (i, j)'s Lagrange weight and its derivatives in (s, t): position, d/ds,
// d/dt, d2/ds2, d2/dsdt, d2/dt2 (the first `Count`), from the factors of z1 = 4 s, z2 = 4 t,
// z0 = 4 - z1 - z2.
template <int Count>
std::array<double, 6> lattice_weight(int i, int j, const Factors& f1, const Factors& f2, const Factors& f0) {
  const int k = kDegree - i - j;
  const double a = f1[size_t(i)][0], da = f1[size_t(i)][1], dda = f1[size_t(i)][2];
  const double b = f2[size_t(j)][0], db = f2[size_t(j)][1], ddb = f2[size_t(j)][2];
  const double c = f0[size_t(k)][0], dc = f0[size_t(k)][1], ddc = f0[size_t(k)][2];
  // The chain rule in barycentric coordinates.
  const double d = kDegree, dd = d * d;
  std::array<double, 6> w{};
  w[0] = a * b * c;
  if constexpr (Count >= 3) {
    w[1] = d * (da * b * c - a * b * dc);
    w[2] = d * (a * db * c - a * b * dc);
  }
  if constexpr (Count >= 6) {
    w[3] = dd * (dda * b * c - 2 * da * b * dc + a * b * ddc);
    w[4] = dd * (da * db * c - da * b * dc - a * db * dc + a * b * ddc);
    w[5] = dd * (a * ddb * c - 2 * a * db * dc + a * b * ddc);
  }
  return w;
}

int row_count(int order) { return order >= 2 ? 6 : order == 1 ? 3 : 1; }

// out[n][l] = the sum over the lattice points q, in order, of weight_q[n] row_q[l], for
// `Count` rows n. Summed per entry from 0 without skipping zeros: a product with a zero
// entry of a row is a zero, which leaves a sum that starts at +0 as it was, so the bits are
// those of skipping it, and the loops are free of branches (and run along the labels).
template <int Count>
void accumulate(const std::vector<std::vector<double>>& rows, const Uv& st, double* const* out) {
  const size_t labels = rows.front().size();
  const auto points = lattice();
  const double z1 = kDegree * st[0], z2 = kDegree * st[1], z0 = kDegree - z1 - z2;
  const Factors f1 = factors(z1), f2 = factors(z2), f0 = factors(z0);
  for (size_t n = 0; n < size_t(Count); ++n) std::fill(out[n], out[n] + labels, 0.0);
  for (size_t q = 0; q < size_t(kQuarticLattice); ++q) {
    const std::array<double, 6> weight = lattice_weight<Count>(points[q][0], points[q][1], f1, f2, f0);
    const double* row = rows[q].data();
    for (size_t n = 0; n < size_t(Count); ++n) {
      double* o = out[n];
      const double w = weight[n];
      for (size_t l = 0; l < labels; ++l) o[l] += w * row[l];
    }
  }
}

void accumulate(const std::vector<std::vector<double>>& rows, const Uv& st, int count, double* const* out) {
  if (count == 1) return accumulate<1>(rows, st, out);
  if (count == 3) return accumulate<3>(rows, st, out);
  accumulate<6>(rows, st, out);
}

}  // namespace

CornerRows quartic_rows(const std::vector<std::vector<double>>& rows, const Uv& st, int order) {
  const size_t labels = rows.front().size();
  CornerRows r;
  // Position; then d/ds, d/dt; then the second derivatives.
  const int count = row_count(order);
  std::vector<double>* all[6] = {&r.position, &r.ds, &r.dt, &r.dss, &r.dst, &r.dtt};
  double* out[6] = {};
  for (int n = 0; n < count; ++n) all[n]->assign(labels, 0.0), out[n] = all[n]->data();
  accumulate(rows, st, count, out);
  return r;
}

bool quartic_rows_fixed(const std::vector<std::vector<double>>& rows, const Uv& st, int order, FixedRows& r) {
  r.labels = rows.front().size();
  if (r.labels > kFixedLabels) return false;
  r.count = row_count(order);
  double* out[6] = {};
  for (int n = 0; n < r.count; ++n) {
    std::fill(r.row[size_t(n)].begin(), r.row[size_t(n)].begin() + std::ptrdiff_t(r.labels), 0.0);
    out[n] = r.row[size_t(n)].data();
  }
  accumulate(rows, st, r.count, out);
  return true;
}

}  // namespace subdiv
