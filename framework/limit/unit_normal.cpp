#include "framework/limit/unit_normal.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

std::array<double, 3> unit_normal(std::span<const double> du, std::span<const double> dv, double negligible) {
  const auto largest = [](std::span<const double> v) {
    return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  };
  if (!(largest(du) > negligible) || !(largest(dv) > negligible)) return {0, 0, 0};
  const std::array<double, 3> a = scaled(du), b = scaled(dv);
  std::array<double, 3> n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double length = std::hypot(n[0], n[1], n[2]);
  // |a|, |b| >= 1 after scaling: length is at least the sine of their angle.
  if (!(length > 1e-12) || !std::isfinite(length)) return {0, 0, 0};
  for (double& x : n) x /= length;
  return n;
}

double negligible_tangent(std::span<const double> positions) {
  double m = 0;
  for (double x : positions) m = std::max(m, std::abs(x));
  return 64 * std::numeric_limits<double>::epsilon() * m;
}

}  // namespace subdiv
