#include "framework/interpolation/curve_limits.h"

#include <climits>
#include <cmath>
#include <fmt/format.h>
#include <map>

#include "framework/analysis/curve_basis.h"
#include "framework/curve/curve_refine.h"
#include "framework/curve/curve_rules.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// A window is refined until its points near the ends are in the uniform part: a handful of
// levels for any mask; these bounds stop a scheme that never gets there.
constexpr int kMaxWindowLevels = 16;
constexpr Index kMaxWindowPoints = 4'000'000;
constexpr long kUnknown = LONG_MIN;

using Row = std::map<Index, double>;  // a limit row while it is assembled (rows are short)

void check_stationary(const CurveScheme& scheme, const CurveMask& mask) {
  const CurveMask next = curve_mask(scheme, 1);
  if (next.first != mask.first || next.coefficients != mask.coefficients)
    throw Error(fmt::format("curve scheme '{}' changes its rules from level to level; limit points (and so "
                            "progressive interpolation) need a stationary scheme",
                            scheme.name));
}

// Open ends keep their end points (ends "interpolate", or a first end rule that copies it).
bool ends_keep_end_points(const CurveRulesAtLevel& rules) {
  if (rules.ends == CurveEnds::Uniform) return false;
  return !rules.end_rules.empty() && rules.end_rules[0].size() == 1 && rules.end_rules[0][0] == 1.0;
}

// The uniform limit row of point j of a polyline `g` (closed: indices around it).
Row uniform_row(const BasisSamples& phi, std::span<const Index> g, long j, bool closed) {
  Row row;
  const long n = long(g.size());
  for (size_t i = 0; i < phi.at_centre.size(); ++i) {
    if (phi.at_centre[i] == 0.0) continue;
    long at = j - (phi.centre_first + long(i));
    at = closed ? ((at % n) + n) % n : at;
    row[g[size_t(at)]] += phi.at_centre[i];
  }
  return row;
}

// Uniform indices (curve_mask.h: point u of level k sits at parameter u / m^k) of the
// points of each level of a one-polyline window hierarchy; kUnknown where an end rule or
// a point beyond the polyline made the point.
std::vector<long> uniform_indices(const std::vector<long>& parent, const CurveOrigins& origins, long m) {
  std::vector<long> u(origins.rule.size(), kUnknown);
  for (size_t q = 0; q < u.size(); ++q) {
    const long i = origins.index[q];
    if (origins.rule[q] < 0 || i < 0 || i >= long(parent.size()) || parent[size_t(i)] == kUnknown) continue;
    u[q] = m * parent[size_t(i)] + origins.rule[q];
  }
  return u;
}

// Point p of the level sits in the uniform part of the curve: `reach` neighbours on each
// side, with consecutive uniform indices (no end rule or extrapolated point among them).
bool in_uniform_part(const std::vector<long>& u, long p, long reach) {
  if (p - reach < 0 || p + reach >= long(u.size())) return false;
  for (long q = p - reach; q <= p + reach; ++q)
    if (u[size_t(q)] == kUnknown || u[size_t(q)] != u[size_t(p)] + (q - p)) return false;
  return true;
}

// The limit rows of the window's vertices `targets` (0-based in the window `g`, an open
// polyline), from a deep enough refinement of the window.
std::map<long, Row> window_rows(const CurveScheme& scheme, const BasisSamples& phi, std::span<const Index> g,
                                const std::vector<long>& targets, long reach) {
  const long n = long(g.size());
  CurveLevel window;
  window.vertex_count = Index(n);
  for (long i = 0; i < n; ++i) window.vertices.push_back(Index(i));
  window.offsets.push_back(Index(n));
  window.closed.push_back(0);
  const long m = scheme.arity;
  std::map<long, Row> rows;
  std::vector<long> pending = targets;
  CurveHierarchy h{{window}, {}, {}};
  std::vector<std::vector<long>> u{std::vector<long>(size_t(n))};
  for (long i = 0; i < n; ++i) u[0][size_t(i)] = i;
  long scale = 1;  // m^level
  for (int level = 1; level <= kMaxWindowLevels && !pending.empty() && h.levels.back().vertex_count < kMaxWindowPoints;
       ++level) {
    CurveStep step = refine_curve_step(h.levels.back(), evaluate_curve_rules(scheme, level - 1), scheme.name);
    u.push_back(uniform_indices(u.back(), step.origins, m));
    h.levels.push_back(std::move(step.child));
    h.stencils.push_back(std::move(step.stencils));
    scale *= m;
    std::vector<long> still;
    for (long j : pending) {
      // The point at j's centre, parameter j + c, has uniform index (j + c) m^level.
      const double at = (double(j) + phi.centre) * double(scale);
      const long target = std::lround(at);
      long p = -1;
      if (std::abs(at - double(target)) < 1e-9)
        for (size_t q = 0; q < u.back().size(); ++q)
          if (u.back()[q] == target) p = long(q);
      if (p < 0 || !in_uniform_part(u.back(), p, reach)) {
        still.push_back(j);
        continue;
      }
      // The uniform limit row at level `level`, carried back to the window's vertices.
      std::vector<double> x(u.back().size(), 0.0);
      for (size_t i = 0; i < phi.at_integers.size(); ++i) x[size_t(p - (phi.integers_first + long(i)))] += phi.at_integers[i];
      for (int l = level - 1; l >= 0; --l) {
        const StencilTable& S = h.stencils[size_t(l)];
        std::vector<double> y(size_t(S.source_count), 0.0);
        for (Index r = 0; r < S.row_count(); ++r)
          if (x[size_t(r)] != 0.0)
            for (Index e = S.offsets[r]; e < S.offsets[r + 1]; ++e) y[size_t(S.indices[e])] += x[size_t(r)] * S.weights[e];
        x = std::move(y);
      }
      Row& row = rows[j];
      for (long i = 0; i < n; ++i)
        if (x[size_t(i)] != 0.0) row[g[size_t(i)]] += x[size_t(i)];
    }
    pending = std::move(still);
  }
  if (!pending.empty())
    throw Error(fmt::format("curve scheme '{}': the limit point of vertex {} near the end of an open polyline "
                            "was not found after refining a window of the polyline {} levels",
                            scheme.name, g[size_t(pending.front())], h.levels.size() - 1));
  return rows;
}

// A point on several polylines (where they meet) must get the same limit from each.
void set_row(std::vector<Row>& rows, std::vector<std::uint8_t>& done, Index v, Row row, const std::string& scheme) {
  if (done[size_t(v)]) {
    double gap = 0;
    for (const auto& [index, weight] : row) gap = std::max(gap, std::abs(rows[size_t(v)][index] - weight));
    for (const auto& [index, weight] : rows[size_t(v)]) gap = std::max(gap, std::abs(row[index] - weight));
    if (gap > 1e-12)
      throw Error(fmt::format("curve scheme '{}': point {} lies on two polylines that give it different limit points "
                              "(an end of one is inside another); split the point into one per polyline",
                              scheme, v));
  }
  rows[size_t(v)] = std::move(row);
  done[size_t(v)] = 1;
}

void append(StencilTable& table, const Row& row) {
  for (const auto& [index, weight] : row) table.indices.push_back(index), table.weights.push_back(weight);
  table.offsets.push_back(Index(table.indices.size()));
}

}  // namespace

StencilTable curve_limit_stencils(const CurveScheme& scheme, const CurveLevel& level) {
  if (scheme.nonlinear)
    throw Error(fmt::format("curve scheme '{}' is not linear: it has no limit rows to interpolate with", scheme.name));
  const CurveMask mask = trimmed(curve_mask(scheme, 0));
  check_stationary(scheme, mask);
  const BasisSamples phi = sample_basis(mask, scheme.name);
  const CurveRulesAtLevel rules = evaluate_curve_rules(scheme, 0);
  // How far the end rules reach into the curve, in points of any level: a mask width on
  // each side of the point, and the widths of the levels after it.
  const long width = long(mask.coefficients.size());
  const long reach = 3 * width + 2, near_end = 2 * width + 2;

  std::vector<Row> rows(size_t(level.vertex_count));
  std::vector<std::uint8_t> done(size_t(level.vertex_count), 0);
  for (Index p = 0; p < level.polyline_count(); ++p) {
    const auto g = level.polyline(p);
    const long n = long(g.size());
    if (level.is_closed(p)) {
      for (long j = 0; j < n; ++j) set_row(rows, done, g[size_t(j)], uniform_row(phi, g, j, true), scheme.name);
      continue;
    }
    if (!ends_keep_end_points(rules))
      throw Error(fmt::format("curve scheme '{}': its open polylines do not keep their end points (ends \"{}\"), so "
                              "their end vertices have no limit point; close the polyline (repeat its first point "
                              "at the end) or use a scheme with ends \"interpolate\"",
                              scheme.name, rules.ends == CurveEnds::Uniform ? "uniform" : "rules"));
    // Ends, then the vertices far from both ends, then those near an end through windows.
    std::vector<long> near_start, near_finish;
    for (long j = 0; j < n; ++j) {
      const Index v = g[size_t(j)];
      if (j == 0 || j == n - 1) set_row(rows, done, v, {{v, 1.0}}, scheme.name);
      else if (j >= near_end && n - 1 - j >= near_end) set_row(rows, done, v, uniform_row(phi, g, j, false), scheme.name);
      else (j < n / 2 ? near_start : near_finish).push_back(j);
    }
    const long span = near_end + reach + width;  // window length: the near points and room beyond them
    if (n <= 2 * span) {
      std::vector<long> all = near_start;
      all.insert(all.end(), near_finish.begin(), near_finish.end());
      for (auto& [j, row] : window_rows(scheme, phi, g, all, reach)) set_row(rows, done, g[size_t(j)], row, scheme.name);
      continue;
    }
    for (auto& [j, row] : window_rows(scheme, phi, g.subspan(0, size_t(span)), near_start, reach))
      set_row(rows, done, g[size_t(j)], row, scheme.name);
    std::vector<long> local;
    for (long j : near_finish) local.push_back(j - (n - span));
    for (auto& [j, row] : window_rows(scheme, phi, g.subspan(size_t(n - span)), local, reach))
      set_row(rows, done, g[size_t(j + n - span)], row, scheme.name);
  }
  StencilTable table;
  table.source_count = level.vertex_count;
  for (Index v = 0; v < level.vertex_count; ++v) append(table, done[size_t(v)] ? rows[size_t(v)] : Row{{v, 1.0}});
  return table;
}

}  // namespace subdiv
