// `subdiv evaluate --at POINTS.csv`: the points file parsed (framework/pipeline/points_file)
// with the real check of a Catmull-Clark limit surface (LimitSurface::check: the face exists,
// (u, v) lies in its domain), and every accepted point evaluated, as the command does. The
// base mesh holds a quad, a triangle and a pentagon around an extraordinary vertex and one
// hole, so faces of every kind and the refused hole are reachable.
//
// Beyond "only subdiv::Error": every accepted point must be one the check accepts, lie in
// its face's domain (Bfr's: [0, 1]^2, an n-gon's sub-faces tiled on a wider grid), and
// evaluate to finite numbers; the parser must keep face and (u, v) in step.
#include <cmath>

#include "fuzz_support.h"
#include "framework/io/mesh_level.h"
#include "framework/limit/face_domain.h"
#include "framework/limit/limit_surface.h"
#include "framework/pipeline/points_file.h"
#include "framework/scheme/scheme_registry.h"

namespace {

using subdiv::Index;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_points_file: %s\n", what.c_str());
  std::abort();
}

// A 3x3 grid of quads whose centre is split into a triangle and a pentagon, lifted so that
// the surface is not flat; the last face is a hole.
subdiv::MeshData base_mesh() {
  subdiv::MeshData m;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) m.positions.insert(m.positions.end(), {double(i), double(j), double((i * j) % 3)});
  m.positions.insert(m.positions.end(), {1.5, 1.2, 2.0});  // vertex 16, splits the centre quad
  const std::vector<std::vector<Index>> faces = {{0, 1, 5, 4},  {1, 2, 6, 5},   {2, 3, 7, 6},
                                                 {4, 5, 9, 8},  {5, 6, 16},     {5, 16, 6, 10, 9},
                                                 {6, 7, 11, 10}, {8, 9, 13, 12}, {9, 10, 14, 13},
                                                 {10, 11, 15, 14}};
  for (const auto& f : faces) {
    m.face_vertices.insert(m.face_vertices.end(), f.begin(), f.end());
    m.face_offsets.push_back(Index(m.face_vertices.size()));
  }
  m.holes.push_back(9);
  return m;
}

const subdiv::MeshData& mesh() {
  static const subdiv::MeshData m = base_mesh();
  return m;
}

const subdiv::LimitSurface& surface() {
  static const subdiv::LimitSurface s(subdiv::load_scheme("catmull-clark"),
                                      subdiv::level_from_mesh(mesh(), "fuzz-base.obj"));
  return s;
}

// The largest u or v of a face's domain in Bfr's parameterisation under a quad split: 1 for
// a quad, the grid width of its sub-faces for any other face (a triangle's tiles span [0, 2],
// a pentagon's [0, 3]).
double extent(Index face) {
  const Index n = mesh().face_offsets[size_t(face) + 1] - mesh().face_offsets[size_t(face)];
  return n == 4 ? 1.0 : double(subdiv::sub_face_columns(int(n)));
}

void check_points(const subdiv::SurfacePoints& points) {
  if (points.uv.size() != 2 * points.faces.size()) finding("faces and (u, v) out of step");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double u = points.uv[2 * i], v = points.uv[2 * i + 1];
    if (!surface().check(points.faces[i], u, v).empty()) finding("a point the check refuses was accepted");
    if (!(u >= 0 && u <= extent(points.faces[i]) && v >= 0 && v <= extent(points.faces[i])))
      finding("an accepted (u, v) outside the face's domain");
    const subdiv::LimitSample s = surface().evaluate(points.faces[i], u, v, mesh().positions, 3, 1);
    for (const double x : s.position)
      if (!std::isfinite(x)) finding("a limit point is not finite");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const subdiv::PointCheck check = [](Index face, double u, double v) { return surface().check(face, u, v); };
  subdiv::fuzz::expect_only_subdiv_errors([&] { check_points(subdiv::parse_points(text, "points.csv", check)); });
  return 0;
}
