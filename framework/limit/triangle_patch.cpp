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

// The lattice point q's Lagrange weight and its derivatives in (s, t): position, d/ds, d/dt,
// d2/ds2, d2/dsdt, d2/dt2.
std::array<double, 6> lattice_weight(int i, int j, const Uv& st) {
  const int k = kDegree - i - j;
  const double z1 = kDegree * st[0], z2 = kDegree * st[1], z0 = kDegree - z1 - z2;
  double a, da, dda, b, db, ddb, c, dc, ddc;
  lagrange_factor(i, z1, a, da, dda);
  lagrange_factor(j, z2, b, db, ddb);
  lagrange_factor(k, z0, c, dc, ddc);
  // z1 = 4 s, z2 = 4 t, z0 = 4 - z1 - z2: the chain rule in barycentric coordinates.
  const double d = kDegree, dd = d * d;
  const double w = a * b * c;
  const double ws = d * (da * b * c - a * b * dc), wt = d * (a * db * c - a * b * dc);
  const double wss = dd * (dda * b * c - 2 * da * b * dc + a * b * ddc);
  const double wst = dd * (da * db * c - da * b * dc - a * db * dc + a * b * ddc);
  const double wtt = dd * (a * ddb * c - 2 * a * db * dc + a * b * ddc);
  return {w, ws, wt, wss, wst, wtt};
}

int row_count(int order) { return order >= 2 ? 6 : order == 1 ? 3 : 1; }

// Adds each lattice point's weights times its row to out[n] (labels entries each).
void accumulate(const std::vector<std::vector<double>>& rows, const Uv& st, int count, double* const* out) {
  const size_t labels = rows.front().size();
  const auto points = lattice();
  for (int q = 0; q < kQuarticLattice; ++q) {
    const std::array<double, 6> weight = lattice_weight(points[size_t(q)][0], points[size_t(q)][1], st);
    const double* row = rows[size_t(q)].data();
    for (size_t l = 0; l < labels; ++l) {
      if (row[l] == 0) continue;
      for (int n = 0; n < count; ++n) out[n][l] += weight[size_t(n)] * row[l];
    }
  }
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
