#include "framework/plugin/polyline_refine.h"

#include <cmath>
#include <fmt/format.h>

#include "framework/rules/formula.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// One step of a linear scheme on a closed polygon: new point m*i + r is
// sum_t w[r][t] * P[(i + start[r] + t) mod N], the weights evaluated at this level.
std::vector<double> linear_closed_step(const CurveScheme& c, std::span<const double> points, int dim, int level) {
  const long n = long(points.size()) / dim;
  FormulaSet formulas(c.parameters, c.definitions);
  std::vector<std::vector<double>> weights(c.arity);
  for (int r = 0; r < c.arity; ++r)
    for (size_t t = 0; t < c.weights[r].size(); ++t)
      weights[r].push_back(formulas.evaluate(formulas.add(c.weights[r][t], fmt::format("{}: rules[{}]", c.path, r)),
                                             {0, 0, double(t), double(level)}));
  std::vector<double> out(size_t(n) * c.arity * dim, 0.0);
  for (long i = 0; i < n; ++i)
    for (int r = 0; r < c.arity; ++r) {
      double* p = &out[(size_t(i) * c.arity + r) * dim];
      for (size_t t = 0; t < weights[r].size(); ++t) {
        const long src = (((i + c.starts[r] + long(t)) % n) + n) % n;
        for (int d = 0; d < dim; ++d) p[d] += weights[r][t] * points[size_t(src) * dim + d];
      }
    }
  return out;
}

}  // namespace

std::vector<double> refine_polyline(const CurveScheme& scheme, std::span<const double> points, int dim, bool closed,
                                    int levels, int first_level) {
  if (dim < 1 || points.size() % size_t(dim) != 0)
    throw Error(fmt::format("refine_polyline: {} numbers are not whole points of dimension {}", points.size(), dim));
  if (closed && points.size() / dim < 3)
    throw Error(fmt::format("{}: a closed polygon needs 3 points or more, not {}", scheme.path, points.size() / dim));
  if (!scheme.nonlinear && !closed)
    throw Error(fmt::format("{}: open polylines with a linear curve scheme are refined by the curve layer "
                            "(framework/curve); refine_polyline takes closed polygons for linear schemes",
                            scheme.path));
  std::vector<double> current(points.begin(), points.end());
  for (int l = 0; l < levels; ++l) {
    const int level = first_level + l;
    std::vector<double> next = scheme.nonlinear ? (*scheme.nonlinear)(current, dim, closed, level)
                                                : linear_closed_step(scheme, current, dim, level);
    if (next.empty() || next.size() % size_t(dim) != 0)
      throw Error(fmt::format("{}: level {} gave {} numbers, not whole points of dimension {}", scheme.path, level,
                              next.size(), dim));
    for (size_t i = 0; i < next.size(); ++i)
      if (!std::isfinite(next[i]))
        throw Error(fmt::format("{}: level {} gave point {} a non-finite coordinate", scheme.path, level, i / dim));
    current = std::move(next);
  }
  return current;
}

}  // namespace subdiv
