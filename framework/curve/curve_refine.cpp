#include "framework/curve/curve_refine.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "framework/analysis/curve/variational_curve.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

constexpr double kOffsetTolerance = 1e-9;

// One stencil row; repeated sources (short closed polygons, extrapolation) are merged.
class Row {
public:
  void add(Index source, double weight) {
    for (auto& [s, w] : terms_)
      if (s == source) {
        w += weight;
        return;
      }
    terms_.push_back({source, weight});
  }
  void clear() { terms_.clear(); }
  bool is_copy_of(Index source) const {
    return terms_.size() == 1 && terms_[0].first == source && terms_[0].second == 1.0;
  }
  void append_to(StencilTable& table) const {
    for (const auto& [s, w] : terms_) {
      table.indices.push_back(s);
      table.weights.push_back(w);
    }
    table.offsets.push_back(Index(table.indices.size()));
  }

private:
  std::vector<std::pair<Index, double>> terms_;
};

struct Point {
  int rule;     // >= 0 scheme rule, < 0 end rule -1 - e
  long index;   // local old point i, or 0 / 1 for the start / end of an open polyline
};

// Adds weight * old point `i` of an open polyline, extrapolating beyond its ends.
void add_open(Row& row, std::span<const Index> g, long i, double weight) {
  const long last = long(g.size()) - 1;
  if (i < 0) {
    const double d = double(-i);
    row.add(g[0], weight * (1.0 + d));
    row.add(g[1], -weight * d);
  } else if (i > last) {
    const double d = double(i - last);
    row.add(g[last], weight * (1.0 + d));
    row.add(g[last - 1], -weight * d);
  } else {
    row.add(g[i], weight);
  }
}

long mod(long a, long n) { return ((a % n) + n) % n; }

std::vector<Point> uniform_points(const CurveRulesAtLevel& rules, long n) {
  std::vector<Point> points;
  const long m = rules.arity;
  // c = m i + r in increasing order.
  long i_lo = n, i_hi = -1;
  for (long r = 0; r < m; ++r) {
    i_lo = std::min(i_lo, long(-rules.starts[r]));
    i_hi = std::max(i_hi, long(n - long(rules.weights[r].size()) - rules.starts[r]));
  }
  for (long i = i_lo; i <= i_hi; ++i)
    for (long r = 0; r < m; ++r) {
      const long first = i + rules.starts[r], last = first + long(rules.weights[r].size()) - 1;
      if (first >= 0 && last <= n - 1) points.push_back({int(r), i});
    }
  return points;
}

std::vector<Point> interpolating_points(const CurveRulesAtLevel& rules, long n) {
  std::vector<Point> points;
  const long m = rules.arity;
  double lowest = 0, highest = 0;
  for (double o : rules.offsets) lowest = std::min(lowest, o), highest = std::max(highest, o);
  const long i_lo = long(std::floor(-highest)) - 1, i_hi = n - 1 + long(std::ceil(-lowest)) + 1;
  for (long i = i_lo; i <= i_hi; ++i)
    for (long r = 0; r < m; ++r) {
      const double at = double(i) + rules.offsets[r];
      if (at >= -kOffsetTolerance && at <= double(n - 1) + kOffsetTolerance) points.push_back({int(r), i});
    }
  auto sits_on = [&](const Point& p, double where) {
    return std::abs(double(p.index) + rules.offsets[p.rule] - where) <= kOffsetTolerance;
  };
  if (points.empty() || !sits_on(points.front(), 0.0)) points.insert(points.begin(), {-1, 0});
  if (points.back().rule < 0 || !sits_on(points.back(), double(n - 1))) points.push_back({-1, 1});
  // The end points themselves (end rule 0), then end rules 1, 2, ... inwards.
  const long e_count = long(rules.end_rules.size());
  for (long e = 0; e < e_count && e < long(points.size()); ++e) {
    points[e] = {int(-1 - e), 0};
    points[points.size() - 1 - e] = {int(-1 - e), 1};
  }
  return points;
}

// A variational scheme's polyline (analysis/curve/variational_curve.h): old points kept
// (an open polyline's end points shared with the polylines ending there), the new points
// from the solved energy, in order along the polyline.
template <class Emit>
void variational_polyline(std::span<const Index> g, bool closed, const CurveRulesAtLevel& rules,
                          const std::string& scheme_name, Row& row, std::vector<Index>& copy_of, CurveLevel& child,
                          Emit& emit) {
  const long n = long(g.size()), per = rules.arity - 1;
  const VariationalEnergy energy{int(rules.arity), rules.variational_alpha, rules.variational_r, scheme_name};
  const std::vector<VariationalRow> rows = variational_rows(energy, n, closed);
  for (long i = 0; i < n; ++i) {
    row.clear();
    row.add(g[i], 1.0);
    const bool end = !closed && (i == 0 || i == n - 1);
    if (end && copy_of[g[i]] != kNone) {
      child.vertices.push_back(copy_of[g[i]]);
    } else {
      if (end) copy_of[g[i]] = child.vertex_count;
      emit(std::int8_t(0), Index(i));
    }
    if (!closed && i == n - 1) break;
    for (long r = 1; r <= per; ++r) {
      row.clear();
      for (const auto& [k, w] : rows[size_t(i * per + r - 1)]) row.add(g[k], w);
      emit(std::int8_t(r), Index(i));
    }
  }
}

}  // namespace

CurveStep refine_curve_step(const CurveLevel& parent, const CurveRulesAtLevel& rules,
                            const std::string& scheme_name) {
  CurveStep step;
  StencilTable& table = step.stencils;
  table.source_count = parent.vertex_count;
  CurveLevel& child = step.child;
  std::vector<Index> copy_of(parent.vertex_count, kNone);  // shared copied end points
  Row row;
  auto emit = [&](std::int8_t rule, Index index) {
    row.append_to(table);
    step.origins.rule.push_back(rule);
    step.origins.index.push_back(index);
    child.vertices.push_back(child.vertex_count++);
  };
  const long m = rules.arity;
  for (Index p = 0; p < parent.polyline_count(); ++p) {
    const auto g = parent.polyline(p);
    const long n = long(g.size());
    if (!rules.variational_alpha.empty()) {
      variational_polyline(g, parent.is_closed(p), rules, scheme_name, row, copy_of, child, emit);
    } else if (parent.is_closed(p)) {
      for (long c = 0; c < m * n; ++c) {
        const long i = c / m, r = c % m;
        row.clear();
        for (size_t t = 0; t < rules.weights[r].size(); ++t)
          row.add(g[mod(i + rules.starts[r] + long(t), n)], rules.weights[r][t]);
        emit(std::int8_t(r), Index(i));
      }
    } else {
      const bool uniform = rules.ends == CurveEnds::Uniform;
      const std::vector<Point> points = uniform ? uniform_points(rules, n) : interpolating_points(rules, n);
      if (uniform && points.size() < 2)
        throw Error(fmt::format("curve scheme {} with ends \"uniform\": open polyline {} of {} points at level "
                                "{} is too short to keep 2 points after the next step; give it more points, "
                                "refine fewer levels, or use ends \"interpolate\"",
                                subdiv::quoted(scheme_name), p + 1, n, rules.level));
      const long e_count = long(rules.end_rules.size());
      if (!uniform && long(points.size()) < 2 * e_count)
        throw Error(fmt::format("curve scheme {}: open polyline {} of {} points at level {} is too short for "
                                "its {} end rules at each end",
                                subdiv::quoted(scheme_name), p + 1, n, rules.level, e_count));
      for (long e = 0; e < e_count; ++e)
        if (long(rules.end_rules[e].size()) > n)
          throw Error(fmt::format("curve scheme {}: end rule {} reads {} points from an end, but open polyline "
                                  "{} has {} points at level {}",
                                  subdiv::quoted(scheme_name), e, rules.end_rules[e].size(), p + 1, n, rules.level));
      for (const Point& pt : points) {
        row.clear();
        if (pt.rule >= 0) {
          for (size_t t = 0; t < rules.weights[pt.rule].size(); ++t)
            add_open(row, g, pt.index + rules.starts[pt.rule] + long(t), rules.weights[pt.rule][t]);
        } else {
          const auto& w = rules.end_rules[size_t(-1 - pt.rule)];
          for (size_t t = 0; t < w.size(); ++t) row.add(pt.index == 0 ? g[t] : g[n - 1 - long(t)], w[t]);
          const Index end_vertex = pt.index == 0 ? g[0] : g[n - 1];
          if (row.is_copy_of(end_vertex)) {
            if (copy_of[end_vertex] != kNone) {
              child.vertices.push_back(copy_of[end_vertex]);
              continue;
            }
            copy_of[end_vertex] = child.vertex_count;
          }
        }
        emit(std::int8_t(pt.rule), Index(pt.index));
      }
    }
    child.offsets.push_back(Index(child.vertices.size()));
    child.closed.push_back(parent.closed[p]);
  }
  return step;
}

CurveHierarchy refine_curves(const CurveScheme& scheme, CurveLevel base, int levels) {
  if (levels < 0) throw OptionError(fmt::format("{{levels}} must be 0 or more, not {}", levels));
  CurveHierarchy h;
  h.levels.push_back(std::move(base));
  for (int l = 0; l < levels; ++l) {
    const CurveRulesAtLevel rules = evaluate_curve_rules(scheme, l);
    CurveStep step = refine_curve_step(h.levels.back(), rules, scheme.name);
    h.levels.push_back(std::move(step.child));
    h.stencils.push_back(std::move(step.stencils));
    h.origins.push_back(std::move(step.origins));
  }
  return h;
}

}  // namespace subdiv
