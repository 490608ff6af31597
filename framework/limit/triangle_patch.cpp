#include "framework/limit/triangle_patch.h"

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

// l_m(z) = prod_{a < m} (z - a) / (m - a) and its derivative in z.
void lagrange_factor(int m, double z, double& value, double& derivative) {
  value = 1, derivative = 0;
  for (int a = 0; a < m; ++a) {
    const double f = (z - a) / (m - a), df = 1.0 / (m - a);
    derivative = derivative * f + value * df;
    value *= f;
  }
}

}  // namespace

Uv quartic_lattice_point(int q) {
  const auto p = lattice()[size_t(q)];
  return {double(p[0]) / kDegree, double(p[1]) / kDegree};
}

CornerRows quartic_rows(const std::vector<std::vector<double>>& rows, const Uv& st) {
  const size_t labels = rows.front().size();
  CornerRows r;
  r.position.assign(labels, 0.0);
  r.ds.assign(labels, 0.0);
  r.dt.assign(labels, 0.0);
  const double z1 = kDegree * st[0], z2 = kDegree * st[1], z0 = kDegree - z1 - z2;
  const auto points = lattice();
  for (int q = 0; q < kQuarticLattice; ++q) {
    const int i = points[size_t(q)][0], j = points[size_t(q)][1], k = kDegree - i - j;
    double a, da, b, db, c, dc;
    lagrange_factor(i, z1, a, da);
    lagrange_factor(j, z2, b, db);
    lagrange_factor(k, z0, c, dc);
    const double w = a * b * c;
    const double ws = kDegree * (da * b * c - a * b * dc), wt = kDegree * (a * db * c - a * b * dc);
    const std::vector<double>& row = rows[size_t(q)];
    for (size_t l = 0; l < labels; ++l) {
      if (row[l] == 0) continue;
      r.position[l] += w * row[l];
      r.ds[l] += ws * row[l];
      r.dt[l] += wt * row[l];
    }
  }
  return r;
}

}  // namespace subdiv
