#include "framework/io/mesh_validate.h"

#include <span>
#include <cmath>
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

// `what` is "face" or "polyline"; min_size is 3 or 2.
void check_csr(std::span<const Index> offsets, std::span<const Index> indices,
               const char* what, int min_size, Index vertex_count, std::string_view context) {
  if (offsets.empty() || offsets.front() != 0)
    fail(context, fmt::format("{} offsets must start with 0", what));
  if (size_t(offsets.back()) != indices.size())
    fail(context, fmt::format("{} offsets end at {} but there are {} {} indices", what,
                              offsets.back(), indices.size(), what));
  // Each element on its own: its offsets within the indices before any index is read.
  const auto good = [&](size_t i) {
    if (offsets[i] < 0 || offsets[i + 1] > offsets.back() || offsets[i + 1] - offsets[i] < min_size) return false;
    for (Index k = offsets[i]; k < offsets[i + 1]; ++k)
      if (indices[k] < 0 || indices[k] >= vertex_count) return false;
    return true;
  };
  if (all_of_parallel(offsets.size() - 1, good)) return;
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
}

void check_positions(const MeshData& mesh, std::string_view context) {
  if (mesh.positions.size() % 3 != 0)
    fail(context, fmt::format("{} coordinates is not a whole number of xyz triples",
                              mesh.positions.size()));
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

void validate_mesh_data(const MeshData& mesh, std::string_view context) {
  check_positions(mesh, context);
  check_csr(mesh.face_offsets, mesh.face_vertices, "face", 3, mesh.vertex_count(), context);
  check_csr(mesh.line_offsets, mesh.line_vertices, "polyline", 2, mesh.vertex_count(), context);
  check_tags(mesh, context);
  check_data_arrays(mesh.point_data, mesh.vertex_count(), "point", context);
  check_data_arrays(mesh.cell_data, mesh.face_count(), "face", context);
  check_face_varying(mesh, context);
}

}  // namespace subdiv
