#pragma once
// Helpers for the curve tests: polylines, refinement in one call, and an independent
// uniform B-spline evaluator (de Boor's algorithm, de Boor 1972) to check refined polygons
// against.
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "framework/curve/curve_refine.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"

namespace subdiv::test {

using Vec3 = std::array<double, 3>;

inline double distance(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

inline Vec3 point(const std::vector<double>& xyz, long i) { return {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; }

// One polyline through all `count` vertices, open or closed.
inline CurveLevel single_polyline(Index count, bool closed) {
  CurveLevel level;
  level.vertex_count = count;
  for (Index i = 0; i < count; ++i) level.vertices.push_back(i);
  level.offsets.push_back(count);
  level.closed.push_back(closed ? 1 : 0);
  return level;
}

// A fixed, irregular space curve's control points (no symmetry that could hide an error).
inline std::vector<double> wiggly_points(int count) {
  std::vector<double> p;
  for (int i = 0; i < count; ++i) {
    p.push_back(i + 0.3 * std::sin(1.7 * i));
    p.push_back(std::cos(0.9 * i) + 0.1 * i * i / count);
    p.push_back(0.5 * std::sin(0.4 * i + 1.0));
  }
  return p;
}

struct RefinedCurve {
  CurveHierarchy hierarchy;
  std::vector<std::vector<double>> positions;  // per level
};

inline RefinedCurve refine_polyline(const CurveScheme& scheme, const std::vector<double>& points, bool closed,
                                    int levels) {
  RefinedCurve r;
  r.hierarchy = refine_curves(scheme, single_polyline(Index(points.size() / 3), closed), levels);
  r.positions.push_back(points);
  for (int l = 0; l < levels; ++l) r.positions.push_back(r.hierarchy.stencils[l].apply(r.positions.back(), 3));
  return r;
}

// Uniform B-spline of degree d whose control point j has the basis N_{d+1}(t - j - shift),
// N_{d+1} the order d+1 B-spline on the knots 0, 1, ..., d+1 (support [shift + j,
// shift + j + d + 1]). de Boor's algorithm (de Boor 1972), with knots t_i = i + shift:
// find r with t_r <= t < t_{r+1}, start from d_{r-d} .. d_r and for s = 1 .. d let
// d_i = (1 - a) d_{i-1} + a d_i, a = (t - t_i)/(t_{i+d+1-s} - t_i), i = r down to r - d + s.
// `control(j)` gives control point j for any integer j; the caller decides what exists.
inline Vec3 de_boor(int degree, double shift, double t, const std::function<Vec3(long)>& control) {
  const long r = long(std::floor(t - shift));
  std::vector<Vec3> d(size_t(degree) + 1);
  for (int q = 0; q <= degree; ++q) d[q] = control(r - degree + q);
  auto knot = [&](long i) { return double(i) + shift; };
  for (int s = 1; s <= degree; ++s)
    for (int q = degree; q >= s; --q) {
      const long i = r - degree + q;
      const double a = (t - knot(i)) / (knot(i + degree + 1 - s) - knot(i));
      for (int c = 0; c < 3; ++c) d[q][c] = (1 - a) * d[q - 1][c] + a * d[q][c];
    }
  return d[degree];
}

// Control indices the de Boor evaluation at t reads: r - d .. r.
inline std::pair<long, long> de_boor_support(int degree, double shift, double t) {
  const long r = long(std::floor(t - shift));
  return {r - degree, r};
}

inline std::filesystem::path write_temp_scheme(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "subdivkit-curve-scheme-tests";
  std::filesystem::create_directories(dir);
  const auto file = dir / (name + ".json");
  std::ofstream(file) << text;
  return file;
}

// The scheme with another end treatment (the library reads ends from the file; tests
// switch them on a copy).
inline CurveScheme with_ends(const CurveScheme& scheme, CurveEnds ends) {
  CurveScheme copy = scheme;
  copy.ends = ends;
  copy.end_rules.clear();
  return copy;
}

}  // namespace subdiv::test
