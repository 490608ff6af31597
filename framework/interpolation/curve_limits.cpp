#include "framework/interpolation/curve_limits.h"

#include <climits>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <unordered_map>

#include "framework/analysis/curve/curve_basis.h"
#include "framework/curve/curve_refine.h"
#include "framework/curve/curve_rules.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// A window is refined until its points near the ends are in the uniform part: a handful of
// levels for any mask; these bounds stop a scheme that never gets there.
constexpr int kMaxWindowLevels = 16;
constexpr Index kMaxWindowPoints = 4'000'000;
constexpr long kUnknown = LONG_MIN;

using Row = std::map<Index, double>;  // a limit row while it is assembled (rows are short)

void check_stationary(const CurveScheme& scheme, const CurveMask& mask) {
  const CurveMask next = trimmed(curve_mask(scheme, 1));
  if (next.first != mask.first || next.coefficients != mask.coefficients)
    throw Error(fmt::format("curve scheme {} changes its rules from level to level; limit points (and so "
                            "progressive interpolation) need a stationary scheme",
                            subdiv::quoted(scheme.name)));
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

// x S: a row over a step's child points carried back to its parent points.
std::vector<double> carry_back(const std::vector<double>& x, const StencilTable& S) {
  std::vector<double> y(size_t(S.source_count), 0.0);
  for (Index r = 0; r < S.row_count(); ++r)
    if (x[size_t(r)] != 0.0)
      for (Index e = S.offsets[r]; e < S.offsets[r + 1]; ++e) y[size_t(S.indices[e])] += x[size_t(r)] * S.weights[e];
  return y;
}

// The limit rows of the window's vertices `targets` (0-based in the window `g`, an open
// polyline), from a deep enough refinement of the window.
std::map<long, Row> window_rows(const CurveScheme& scheme, const BasisSamples& phi, std::span<const Index> g,
                                const std::vector<long>& targets, long reach) {
  const long n = long(g.size());
  CurveLevel level;  // the window as a polyline of its own, points 0 .. n-1
  level.vertex_count = Index(n);
  for (long i = 0; i < n; ++i) level.vertices.push_back(Index(i));
  level.offsets.push_back(Index(n));
  level.closed.push_back(0);
  std::vector<long> u(level.vertices.begin(), level.vertices.end());  // uniform indices of the level's points
  std::vector<StencilTable> stencils;
  std::map<long, Row> rows;
  std::vector<long> pending = targets;
  long scale = 1;  // m^level
  while (!pending.empty() && int(stencils.size()) < kMaxWindowLevels && level.vertex_count < kMaxWindowPoints) {
    CurveStep step = refine_curve_step(level, evaluate_curve_rules(scheme, int(stencils.size())), scheme.name);
    u = uniform_indices(u, step.origins, scheme.arity);
    level = std::move(step.child);
    stencils.push_back(std::move(step.stencils));
    scale *= scheme.arity;
    std::unordered_map<long, long> point_of;  // uniform index -> point
    for (size_t q = 0; q < u.size(); ++q)
      if (u[q] != kUnknown) point_of.emplace(u[q], long(q));
    std::vector<long> still;
    for (long j : pending) {
      // The point at j's centre, parameter j + c, has uniform index (j + c) m^level.
      const double at = (double(j) + phi.centre) * double(scale);
      const auto found = std::abs(at - std::round(at)) < 1e-9 ? point_of.find(std::lround(at)) : point_of.end();
      if (found == point_of.end() || !in_uniform_part(u, found->second, reach)) {
        still.push_back(j);
        continue;
      }
      // The uniform limit row at this level, carried back to the window's vertices.
      std::vector<double> x(u.size(), 0.0);
      for (size_t i = 0; i < phi.at_integers.size(); ++i)
        x[size_t(found->second - (phi.integers_first + long(i)))] += phi.at_integers[i];
      for (size_t l = stencils.size(); l-- > 0;) x = carry_back(x, stencils[l]);
      Row& row = rows[j];
      for (long i = 0; i < n; ++i)
        if (x[size_t(i)] != 0.0) row[g[size_t(i)]] += x[size_t(i)];
    }
    pending = std::move(still);
  }
  if (!pending.empty())
    throw Error(fmt::format("curve scheme {}: the limit point of vertex {} near the end of an open polyline "
                            "was not found after refining a window of the polyline {} levels",
                            subdiv::quoted(scheme.name), g[size_t(pending.front())], stencils.size()));
  return rows;
}

// A point on several polylines (where they meet) must get the same limit from each.
void set_row(std::vector<Row>& rows, Index v, Row row, const std::string& scheme) {
  if (!rows[size_t(v)].empty()) {
    double gap = 0;
    for (const auto& [index, weight] : row) gap = std::max(gap, std::abs(rows[size_t(v)][index] - weight));
    for (const auto& [index, weight] : rows[size_t(v)]) gap = std::max(gap, std::abs(row[index] - weight));
    if (gap > 1e-12)
      throw Error(fmt::format("curve scheme {}: point {} lies on two polylines that give it different limit points "
                              "(an end of one is inside another); split the point into one per polyline",
                              subdiv::quoted(scheme), v));
  }
  rows[size_t(v)] = std::move(row);
}

void append(StencilTable& table, const Row& row) {
  for (const auto& [index, weight] : row) table.indices.push_back(index), table.weights.push_back(weight);
  table.offsets.push_back(Index(table.indices.size()));
}

}  // namespace

StencilTable curve_limit_stencils(const CurveScheme& scheme, const CurveLevel& level) {
  if (scheme.nonlinear)
    throw Error(fmt::format("curve scheme {} is not linear: it has no limit rows to interpolate with", subdiv::quoted(scheme.name)));
  const CurveMask mask = trimmed(curve_mask(scheme, 0));
  check_stationary(scheme, mask);
  const BasisSamples phi = sample_basis(mask, scheme.name);
  const CurveRulesAtLevel rules = evaluate_curve_rules(scheme, 0);
  // How far the end rules reach into the curve, in points of any level: a mask width on
  // each side of the point, and the widths of the levels after it.
  const long width = long(mask.coefficients.size());
  const long reach = 3 * width + 2, near_end = 2 * width + 2;

  std::vector<Row> rows(size_t(level.vertex_count));  // empty: on no polyline
  for (Index p = 0; p < level.polyline_count(); ++p) {
    const auto g = level.polyline(p);
    const long n = long(g.size());
    if (level.is_closed(p)) {
      for (long j = 0; j < n; ++j) set_row(rows, g[size_t(j)], uniform_row(phi, g, j, true), scheme.name);
      continue;
    }
    if (!ends_keep_end_points(rules))
      throw Error(fmt::format("curve scheme {}: its open polylines do not keep their end points (ends \"{}\"), so "
                              "their end vertices have no limit point; close the polyline (repeat its first point "
                              "at the end) or use a scheme with ends \"interpolate\"",
                              subdiv::quoted(scheme.name), escaped(rules.ends == CurveEnds::Uniform ? "uniform" : "rules")));
    // Ends, then the vertices far from both ends, then those near an end through windows.
    std::vector<long> near_start, near_finish;
    for (long j = 0; j < n; ++j) {
      const Index v = g[size_t(j)];
      if (j == 0 || j == n - 1) set_row(rows, v, {{v, 1.0}}, scheme.name);
      else if (j >= near_end && n - 1 - j >= near_end) set_row(rows, v, uniform_row(phi, g, j, false), scheme.name);
      else (j < n / 2 ? near_start : near_finish).push_back(j);
    }
    // The rows of vertices `near` from a window of `length` points starting at `from`.
    auto from_window = [&](long from, long length, const std::vector<long>& near) {
      std::vector<long> local;
      for (long j : near) local.push_back(j - from);
      for (auto& [j, row] : window_rows(scheme, phi, g.subspan(size_t(from), size_t(length)), local, reach))
        set_row(rows, g[size_t(j + from)], std::move(row), scheme.name);
    };
    const long span = near_end + reach + width;  // window length: the near points and room beyond them
    if (n <= 2 * span) {
      near_start.insert(near_start.end(), near_finish.begin(), near_finish.end());
      from_window(0, n, near_start);
    } else {
      from_window(0, span, near_start);
      from_window(n - span, span, near_finish);
    }
  }
  StencilTable table;
  table.source_count = level.vertex_count;
  for (Index v = 0; v < level.vertex_count; ++v) append(table, rows[size_t(v)].empty() ? Row{{v, 1.0}} : rows[size_t(v)]);
  return table;
}

}  // namespace subdiv
