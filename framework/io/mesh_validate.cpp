#include "framework/io/mesh_validate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

[[noreturn]] void fail(std::string_view context, const std::string& problem) {
  throw Error(fmt::format("{}: {}", context, problem));
}

// Whether `good(i)` holds for every i < n, on every core. The checks below run this first
// and walk the elements in order only when something is wrong, so that the message names
// the first problem, as before; a 16M-face level is checked before each write.
template <class Good>
bool all_of_parallel(std::size_t n, const Good& good) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, 1 << 14), true,
      [&](const tbb::blocked_range<std::size_t>& r, bool ok) {
        for (std::size_t i = r.begin(); ok && i != r.end(); ++i) ok = good(i);
        return ok;
      },
      [](bool a, bool b) { return a && b; });
}

// Whether every element has at least min_size indices, i.e. the offsets (which start at 0)
// grow by at least min_size from each to the next: a branch-free pass that the compiler
// vectorises. Then they also stay within 0 and their last.
bool steps_at_least(std::span<const Index> offsets, int min_size) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, offsets.size() - 1, 1 << 16), true,
      [&](const tbb::blocked_range<std::size_t>& r, bool ok) {
        if (!ok) return false;
        int short_step = 0;
        for (std::size_t i = r.begin(); i != r.end(); ++i)
          short_step |= int((long long)offsets[i + 1] - (long long)offsets[i] < min_size);  // no overflow
        return short_step == 0;
      },
      [](bool a, bool b) { return a && b; });
}

struct IndexRange {
  Index min = std::numeric_limits<Index>::max(), max = std::numeric_limits<Index>::min();
  IndexRange join(const IndexRange& o) const { return {std::min(min, o.min), std::max(max, o.max)}; }
};

// The smallest and largest index: one vectorised pass, which both checks the indices (with
// steps_at_least every index belongs to an element) and gives writers their range.
IndexRange index_range(std::span<const Index> indices) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, indices.size(), 1 << 16), IndexRange{},
      [&](const tbb::blocked_range<std::size_t>& r, IndexRange range) {
        Index lo = range.min, hi = range.max;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          lo = indices[i] < lo ? indices[i] : lo;
          hi = indices[i] > hi ? indices[i] : hi;
        }
        return IndexRange{lo, hi};
      },
      [](const IndexRange& a, const IndexRange& b) { return a.join(b); });
}

// `what` is "face" or "polyline"; min_size is 3 or 2. Returns the indices' range (min > max
// when there are none).
IndexRange check_csr(std::span<const Index> offsets, std::span<const Index> indices,
                     const char* what, int min_size, Index vertex_count, std::string_view context) {
  if (offsets.empty() || offsets.front() != 0)
    fail(context, fmt::format("{} offsets must start with 0", what));
  if (size_t(offsets.back()) != indices.size())
    fail(context, fmt::format("{} offsets end at {} but there are {} {} indices", what,
                              offsets.back(), indices.size(), what));
  if (steps_at_least(offsets, min_size)) {
    const IndexRange range = index_range(indices);
    if (indices.empty() || (range.min >= 0 && range.max < vertex_count)) return range;
  }
  // Something is wrong: element by element in order, so that the message names the first problem.
  for (size_t i = 0; i + 1 < offsets.size(); ++i) {
    const Index size = offsets[i + 1] - offsets[i];
    if (offsets[i + 1] > offsets.back())
      fail(context, fmt::format("{} offsets are not increasing at {} {}", what, what, i));
    if (size < min_size)
      fail(context, fmt::format("{} {} has {} vertices; a {} needs at least {}", what, i, size,
                                what, min_size));
    for (Index k = offsets[i]; k < offsets[i + 1]; ++k)
      if (indices[k] < 0 || indices[k] >= vertex_count)
        fail(context, fmt::format("{} {} refers to vertex {}, but the mesh has {} vertices "
                                  "(numbered from 0)",
                                  what, i, indices[k], vertex_count));
  }
  fail(context, fmt::format("{} offsets are not increasing", what));  // not reached: the walk names the problem
}

// The smallest and largest squared norm of the points, and whether every one was finite.
struct NormSquares {
  double min = std::numeric_limits<double>::infinity(), max = 0;
  bool finite = true;
  NormSquares join(const NormSquares& o) const { return {std::min(min, o.min), std::max(max, o.max), finite && o.finite}; }
};

// One branch-free pass over the coordinates. A squared norm is finite exactly when the
// point's coordinates are and their squares do not overflow. Summed as
// vtk_array_ranges.cpp's range_of sums them (0 + x*x + y*y + z*z, in that order), and the
// square root is monotonic and correctly rounded, so the square roots of these bounds are
// the bounds of the norms, bit for bit.
NormSquares norm_squares(std::span<const double> positions) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, positions.size() / 3, 1 << 15), NormSquares{},
      [&](const tbb::blocked_range<std::size_t>& r, NormSquares range) {
        double lo = range.min, hi = range.max;
        int infinite = 0;
        const double* p = positions.data();
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          double n = 0;
          n += p[3 * i] * p[3 * i];
          n += p[3 * i + 1] * p[3 * i + 1];
          n += p[3 * i + 2] * p[3 * i + 2];
          infinite |= int(!(n <= std::numeric_limits<double>::max()));  // inf or NaN
          lo = n < lo ? n : lo;
          hi = n > hi ? n : hi;
        }
        return range.join({lo, hi, infinite == 0});
      },
      [](const NormSquares& a, const NormSquares& b) { return a.join(b); });
}

// Also the points' norm range into `ranges` (not null) when it is known.
void check_positions(const MeshData& mesh, std::string_view context, MeshValueRanges* ranges) {
  if (mesh.positions.size() % 3 != 0)
    fail(context, fmt::format("{} coordinates is not a whole number of xyz triples",
                              mesh.positions.size()));
  if (mesh.positions.empty()) return;
  const NormSquares squares = norm_squares(mesh.positions);
  if (squares.finite) {
    ranges->point_norms_known = true;
    ranges->point_norm_min = std::sqrt(squares.min), ranges->point_norm_max = std::sqrt(squares.max);
    return;
  }
  // Some square is not finite: an overflow of finite coordinates (the norms then unknown
  // here), or a coordinate that is not finite, named in order.
  if (all_of_parallel(mesh.positions.size(), [&](size_t i) { return std::isfinite(mesh.positions[i]); })) return;
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!std::isfinite(mesh.positions[i]))
      fail(context, fmt::format("vertex {} has a non-finite coordinate ({}); fix or remove it",
                                i / 3, mesh.positions[i]));
}

void check_sharpness(double s, std::string_view context, const std::string& tag) {
  if (!std::isfinite(s) || s < 0)
    fail(context, fmt::format("{} has sharpness {}; sharpness must be a finite number >= 0 "
                              "(0 smooth, 10 or more infinitely sharp)",
                              tag, s));
}

void check_tags(const MeshData& mesh, std::string_view context) {
  const Index n = mesh.vertex_count();
  auto missing = [n](Index v) { return v < 0 || v >= n; };
  for (const CreaseTag& c : mesh.creases) {
    const std::string tag = fmt::format("crease {}-{}", c.v0, c.v1);
    if (missing(c.v0) || missing(c.v1))
      fail(context, fmt::format("{} names a vertex that does not exist (the mesh has {} "
                                "vertices, numbered from 0)",
                                tag, n));
    if (c.v0 == c.v1) fail(context, fmt::format("{} joins a vertex to itself", tag));
    check_sharpness(c.sharpness, context, tag);
  }
  for (const CornerTag& c : mesh.corners) {
    const std::string tag = fmt::format("corner {}", c.v);
    if (missing(c.v))
      fail(context, fmt::format("{} names a vertex that does not exist (the mesh has {} "
                                "vertices, numbered from 0)",
                                tag, n));
    check_sharpness(c.sharpness, context, tag);
  }
  for (Index f : mesh.holes)
    if (f < 0 || f >= mesh.face_count())
      fail(context, fmt::format("hole {} names a face that does not exist (the mesh has {} faces, numbered from 0)",
                                f, mesh.face_count()));
}

// Names unique per kind, one tuple per element, integer arrays whole.
void check_data_arrays(const std::vector<DataArray>& arrays, Index tuples, const char* per,
                       std::string_view context) {
  for (size_t i = 0; i < arrays.size(); ++i) {
    const DataArray& a = arrays[i];
    if (a.name.empty()) fail(context, fmt::format("a {} data array has no name", per));
    for (size_t j = 0; j < i; ++j)
      if (arrays[j].name == a.name)
        fail(context, fmt::format("two {} data arrays are named {}", per, subdiv::quoted(a.name)));
    if (a.components < 1)
      fail(context, fmt::format("{} data array {} has {} components; it needs at least 1", per, subdiv::quoted(a.name),
                                a.components));
    if (a.values.size() != size_t(tuples) * size_t(a.components))
      fail(context,
           fmt::format("{} data array {} has {} values, but {} {}s x {} components need {}", per, subdiv::quoted(a.name),
                       a.values.size(), tuples, per, a.components, size_t(tuples) * size_t(a.components)));
    if (!a.integer) continue;
    const auto whole = [&](size_t k) { return a.values[k] == std::floor(a.values[k]) && std::abs(a.values[k]) <= 2147483647.0; };
    if (all_of_parallel(a.values.size(), whole)) continue;
    for (size_t k = 0; k < a.values.size(); ++k) {
      const double v = a.values[k];
      if (v != std::floor(v) || std::abs(v) > 2147483647.0)
        fail(context, fmt::format("integer {} data array {} holds {} at {} {}, which is not a whole number that "
                                  "fits an int",
                                  per, subdiv::quoted(a.name), v, per, k / size_t(a.components)));
    }
  }
}

void check_face_varying(const MeshData& mesh, std::string_view context) {
  for (const FaceVaryingArray& a : mesh.face_varying) {
    if (a.components < 1 || a.values.size() % size_t(a.components) != 0)
      fail(context, fmt::format("face-varying array {} has {} values, not a whole number of {}-component tuples",
                                subdiv::quoted(a.name), a.values.size(), a.components));
    if (a.indices.size() != mesh.face_vertices.size())
      fail(context, fmt::format("face-varying array {} has {} corner indices for {} face corners", subdiv::quoted(a.name),
                                a.indices.size(), mesh.face_vertices.size()));
    for (size_t c = 0; c < a.indices.size(); ++c)
      if (a.indices[c] < 0 || a.indices[c] >= a.value_count())
        fail(context, fmt::format("face-varying array {}: face corner {} uses value {}, but there are {} values",
                                  subdiv::quoted(a.name), c, a.indices[c], a.value_count()));
  }
}

}  // namespace

void validate_mesh_data(const MeshData& mesh, std::string_view context, MeshValueRanges* ranges) {
  MeshValueRanges seen;
  check_positions(mesh, context, &seen);
  const IndexRange faces = check_csr(mesh.face_offsets, mesh.face_vertices, "face", 3, mesh.vertex_count(), context);
  if (!mesh.face_vertices.empty()) seen.face_vertices_known = true, seen.face_vertex_min = faces.min, seen.face_vertex_max = faces.max;
  check_csr(mesh.line_offsets, mesh.line_vertices, "polyline", 2, mesh.vertex_count(), context);
  check_tags(mesh, context);
  check_data_arrays(mesh.point_data, mesh.vertex_count(), "point", context);
  check_data_arrays(mesh.cell_data, mesh.face_count(), "face", context);
  check_face_varying(mesh, context);
  if (ranges) *ranges = seen;
}

}  // namespace subdiv
