// STL and OpenMesh's own .om through OpenMesh. STL stores each triangle with its own
// three corners; OpenMesh merges corners with equal coordinates into shared vertices,
// which is the connectivity the engine needs. STL coordinates are 32-bit floats by the
// format's definition.
//
// OpenMesh cannot represent non-manifold meshes: where a face does not fit it duplicates
// the face's vertices. For STL, whose merge makes every vertex position unique, two
// vertices at the same position can only come from such a split, so it is reported
// instead of handing the engine a silently cut mesh.
#include <algorithm>
#include <array>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <fmt/format.h>

#include "framework/io/formats.h"
#include "framework/io/readers.h"
#include "framework/io/om_check.h"
#include "framework/io/stl_check.h"
#include "framework/io/text_input.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

// OpenMesh reports problems on its global error stream; collect them for our message
// instead of letting them interleave with the tool's own output. The stream's buffer is
// swapped for ours while a file is read: OpenMesh's own connect()/disconnect() would leak
// a wrapper object on every call (found by fuzz_read_stl under LeakSanitizer).
class CapturedErrors {
public:
  CapturedErrors() : previous_(::omerr().rdbuf(text_.rdbuf())) {}
  ~CapturedErrors() { ::omerr().rdbuf(previous_); }
  CapturedErrors(const CapturedErrors&) = delete;
  CapturedErrors& operator=(const CapturedErrors&) = delete;
  std::string text() {
    ::omerr().flush();
    std::string s = text_.str();
    std::replace(s.begin(), s.end(), '\n', ' ');
    return s;
  }

private:
  std::ostringstream text_;  // before previous_: constructed first
  std::streambuf* previous_;
};

MeshData to_mesh_data(const PolyMesh& mesh) {
  MeshData out;
  out.positions.reserve(mesh.n_vertices() * 3);
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    out.positions.insert(out.positions.end(), {p[0], p[1], p[2]});
  }
  out.face_offsets.reserve(mesh.n_faces() + 1);
  for (const auto f : mesh.faces()) {
    // Counter-clockwise from the face's first vertex: the order the file listed them.
    for (auto v = mesh.cfv_ccwbegin(f); v != mesh.cfv_ccwend(f); ++v)
      out.face_vertices.push_back(Index(v->idx()));
    out.face_offsets.push_back(Index(out.face_vertices.size()));
  }
  return out;
}

// Counts vertices that share their position with another one.
std::size_t duplicated_positions(const MeshData& mesh) {
  const Index n = mesh.vertex_count();
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), 0);
  const auto point = [&](Index v) {
    return std::array<double, 3>{mesh.positions[3 * v], mesh.positions[3 * v + 1],
                                 mesh.positions[3 * v + 2]};
  };
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return point(a) < point(b); });
  std::size_t duplicates = 0;
  for (Index i = 1; i < n; ++i) duplicates += point(order[i]) == point(order[i - 1]);
  return duplicates;
}

}  // namespace

MeshData read_with_openmesh(const fs::path& file) {
  require_readable(file);
  if (lowercase_extension(file) == ".stl") check_stl_file(file);  // lines and NaN, which OpenMesh does not report
  if (lowercase_extension(file) == ".om") check_om_file(file);    // OpenMesh trusts every count and id in it
  PolyMesh mesh;
  OpenMesh::IO::Options options;
  std::string errors;
  bool ok;
  {
    CapturedErrors captured;
    ok = OpenMesh::IO::read_mesh(mesh, file.string(), options);
    errors = captured.text();
  }
  if (!ok)
    throw Error(fmt::format("cannot read {}: OpenMesh could not parse it{}{}", subdiv::quoted(file.string()),
                            errors.empty() ? "" : ": ", errors));
  MeshData out = to_mesh_data(mesh);
  if (lowercase_extension(file) == ".stl") {
    if (const std::size_t split = duplicated_positions(out); split > 0)
      throw Error(fmt::format("{}: the mesh is not manifold: OpenMesh had to split {} "
                              "vertices to read it ({}); repair the mesh, or save it as OBJ, "
                              "OFF or PLY, which keep non-manifold faces for a precise report",
                              escaped(file.string()), split, errors.empty() ? "no details" : errors));
  }
  return out;
}

}  // namespace subdiv::io_detail
