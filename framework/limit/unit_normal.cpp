#include "framework/limit/unit_normal.h"

#include <algorithm>
#include <cmath>

namespace subdiv {
namespace {

// `v` divided by its largest component's magnitude (zero stays zero; a non-finite one
// gives NaN, which the caller's check turns into no normal).
std::array<double, 3> scaled(std::span<const double> v) {
  const double m = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  if (m == 0) return {0, 0, 0};
  return {v[0] / m, v[1] / m, v[2] / m};
}

}  // namespace

std::array<double, 3> unit_normal(std::span<const double> du, std::span<const double> dv) {
  const std::array<double, 3> a = scaled(du), b = scaled(dv);
  std::array<double, 3> n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double length = std::hypot(n[0], n[1], n[2]);
  if (!(length > 0) || !std::isfinite(length)) return {0, 0, 0};
  for (double& x : n) x /= length;
  return n;
}

}  // namespace subdiv
