#include "framework/parameterize/boundary_layout.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "framework/util/error.h"

namespace subdiv {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 point(std::span<const double> p, Index v) {
  return {p[size_t(3 * v)], p[size_t(3 * v + 1)], p[size_t(3 * v + 2)]};
}

double distance(std::span<const double> p, Index a, Index b) {
  const Vec3 x = point(p, a), y = point(p, b);
  return std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]);
}

// Arc length at each loop vertex from loop[from], and the loop's total length.
std::vector<double> arc_lengths(std::span<const Index> loop, std::span<const double> p, size_t from, double& total) {
  const size_t n = loop.size();
  std::vector<double> s(n, 0.0);
  total = 0;
  for (size_t k = 0; k < n; ++k) {
    const size_t i = (from + k) % n, j = (i + 1) % n;
    s[i] = total;
    total += distance(p, loop[i], loop[j]);
  }
  return s;
}

// The angle between the incoming and the outgoing boundary edge at loop[i] (0: straight on).
double turn(std::span<const Index> loop, std::span<const double> p, size_t i) {
  const size_t n = loop.size();
  const Vec3 a = point(p, loop[(i + n - 1) % n]), b = point(p, loop[i]), c = point(p, loop[(i + 1) % n]);
  const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - b[0], c[1] - b[1], c[2] - b[2]};
  const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const double lu = std::hypot(u[0], u[1], u[2]), lv = std::hypot(v[0], v[1], v[2]);
  return lu > 0 && lv > 0 ? std::acos(std::clamp(dot / (lu * lv), -1.0, 1.0)) : 0.0;
}

std::vector<size_t> sharpest_turns(std::span<const Index> loop, std::span<const double> p) {
  std::vector<size_t> order(loop.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  // Ties (a regular polygon's equal turns) go to the earlier vertex, so the choice is stable.
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return turn(loop, p, a) > turn(loop, p, b); });
  order.resize(4);
  std::sort(order.begin(), order.end());
  return order;
}

std::vector<size_t> given_corners(std::span<const Index> loop, const std::vector<Index>& corners,
                                  const std::string& source) {
  if (corners.size() != 4)
    throw Error(fmt::format("{}: a square boundary needs 4 corners, {} given", source, corners.size()));
  std::vector<size_t> at;
  for (Index c : corners) {
    const auto it = std::find(loop.begin(), loop.end(), c);
    if (it == loop.end())
      throw Error(fmt::format("{}: corner {} is not a boundary vertex (vertices count from 0); the boundary has {} "
                              "vertices, e.g. {}",
                              source, c, loop.size(), fmt::join(loop.subspan(0, std::min<size_t>(loop.size(), 6)), ", ")));
    at.push_back(size_t(it - loop.begin()));
  }
  std::sort(at.begin(), at.end());
  if (std::adjacent_find(at.begin(), at.end()) != at.end())
    throw Error(fmt::format("{}: the 4 corners {} name a vertex twice; give 4 different boundary vertices", source,
                            fmt::join(corners, ", ")));
  return at;
}

}  // namespace

void circle_layout(std::span<const Index> loop, std::span<const double> positions, std::vector<double>& uv) {
  double total = 0;
  const std::vector<double> s = arc_lengths(loop, positions, 0, total);
  constexpr double kTwoPi = 6.283185307179586476925286766559;
  for (size_t i = 0; i < loop.size(); ++i) {
    const double t = total > 0 ? kTwoPi * s[i] / total : kTwoPi * double(i) / double(loop.size());
    uv[size_t(2 * loop[i])] = std::cos(t);
    uv[size_t(2 * loop[i] + 1)] = std::sin(t);
  }
}

std::vector<Index> square_layout(std::span<const Index> loop, std::span<const double> positions,
                                 std::vector<Index> corners, std::vector<double>& uv, const std::string& source) {
  if (loop.size() < 4)
    throw Error(fmt::format("{}: the boundary has {} vertices; a square boundary needs at least 4 for its corners",
                            source, loop.size()));
  const std::vector<size_t> at = corners.empty() ? sharpest_turns(loop, positions) : given_corners(loop, corners, source);
  constexpr double kCorner[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  const size_t n = loop.size();
  for (int side = 0; side < 4; ++side) {
    const size_t first = at[size_t(side)], last = at[size_t((side + 1) % 4)];
    const size_t count = (last + n - first) % n;  // edges along this side
    double length = 0;
    for (size_t k = 0; k < count; ++k) length += distance(positions, loop[(first + k) % n], loop[(first + k + 1) % n]);
    double s = 0;
    for (size_t k = 0; k < count; ++k) {
      const double t = length > 0 ? s / length : double(k) / double(count);
      const Index v = loop[(first + k) % n];
      uv[size_t(2 * v)] = kCorner[side][0] + t * (kCorner[side + 1][0] - kCorner[side][0]);
      uv[size_t(2 * v + 1)] = kCorner[side][1] + t * (kCorner[side + 1][1] - kCorner[side][1]);
      s += distance(positions, v, loop[(first + k + 1) % n]);
    }
  }
  std::vector<Index> used;
  for (size_t i : at) used.push_back(loop[i]);
  return used;
}

}  // namespace subdiv
