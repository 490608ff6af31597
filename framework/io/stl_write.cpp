// Binary STL: triangles only, 32-bit floats by the format's definition. Polygons are
// split into fans from their first vertex, which is exact for the convex polygons
// subdivision produces.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "framework/io/binary_le.h"
#include "framework/io/writers.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {

namespace {

using Vec = std::array<double, 3>;

Vec point(const MeshData& mesh, Index v) {
  return {mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
}

Vec unit_normal(const Vec& a, const Vec& b, const Vec& c) {
  const Vec u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  Vec n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (length > 0)
    for (double& x : n) x /= length;
  return n;
}

void put_vec(BufferedOutput& out, const Vec& v) {
  for (double x : v) put_le(out, float(x));
}

std::uint64_t triangle_count(const MeshData& mesh) {
  std::uint64_t count = 0;
  for (Index f = 0; f < mesh.face_count(); ++f)
    count += mesh.face_offsets[f + 1] - mesh.face_offsets[f] - 2;
  return count;
}

void check_float_range(const MeshData& mesh, const path& shown) {
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (std::abs(mesh.positions[i]) > std::numeric_limits<float>::max())
      throw Error(fmt::format("cannot write {}: vertex {} has a coordinate ({}) too large for "
                              "STL's 32-bit floats; write PLY or OBJ instead",
                              subdiv::quoted(shown.string()), i / 3, mesh.positions[i]));
}

}  // namespace

void write_stl(const path& file, const path& shown, const MeshData& mesh, const ProgressCallback& progress) {
  check_float_range(mesh, shown);
  const std::uint64_t triangles = triangle_count(mesh);
  if (triangles > std::numeric_limits<std::uint32_t>::max())
    throw Error(fmt::format("cannot write {}: {} triangles exceed binary STL's limit",
                            subdiv::quoted(shown.string()), triangles));
  BufferedOutput out(file, shown);
  // The header must not start with "solid", or readers take the file for ASCII STL.
  char header[80] = {};
  constexpr char kTitle[] = "SubdivKit binary STL";
  std::memcpy(header, kTitle, sizeof kTitle - 1);
  out.write(header, sizeof header);
  put_le(out, std::uint32_t(triangles));
  WriteProgress written(progress, std::size_t(mesh.face_count()));
  for (Index f = 0; f < mesh.face_count(); ++f, written.step()) {
    const Index first = mesh.face_offsets[f];
    for (Index k = first + 1; k + 1 < mesh.face_offsets[f + 1]; ++k) {
      const Vec a = point(mesh, mesh.face_vertices[first]);
      const Vec b = point(mesh, mesh.face_vertices[k]);
      const Vec c = point(mesh, mesh.face_vertices[k + 1]);
      put_vec(out, unit_normal(a, b, c));
      put_vec(out, a);
      put_vec(out, b);
      put_vec(out, c);
      put_le(out, std::uint16_t(0));  // attribute byte count, unused
    }
  }
  out.close();
  written.finish();
}

}  // namespace subdiv::io_detail
