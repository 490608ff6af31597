// subdiv-bench-meshlibs, CGAL's side: Subdivision_method_3 (Loop, Sqrt3, DooSabin,
// CatmullClark) on CGAL::Surface_mesh with Simple_cartesian<double> points, the mesh type
// and kernel of CGAL's own Subdivision_method_3 examples (CGAL 5.5 manual, "3D Surface
// Subdivision Methods"); the other host, Polyhedron_3, is CGAL's older structure.
// CGAL has no modified butterfly.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/version_macros.h>

#include "meshlibs_sides.h"

namespace subdiv_bench {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Refine = void (*)(CgalMesh&, int levels);

void build(const Mesh& mesh, CgalMesh& sm) {
  sm.reserve(CgalMesh::size_type(mesh.vertex_count), CgalMesh::size_type(mesh.face_vertices.size() / 2),
             CgalMesh::size_type(mesh.face_count()));
  for (std::int32_t v = 0; v < mesh.vertex_count; ++v)
    sm.add_vertex(Kernel::Point_3(mesh.xyz[3 * size_t(v)], mesh.xyz[3 * size_t(v) + 1], mesh.xyz[3 * size_t(v) + 2]));
  std::vector<CgalMesh::Vertex_index> corners;
  for (std::int32_t f = 0; f < mesh.face_count(); ++f) {
    corners.clear();
    for (std::int32_t i = mesh.face_offsets[f]; i < mesh.face_offsets[f + 1]; ++i)
      corners.emplace_back(CgalMesh::size_type(mesh.face_vertices[size_t(i)]));
    sm.add_face(corners);
  }
}

// CGAL's documented calls, with the number of iterations as a named parameter.
namespace sm3 = CGAL::Subdivision_method_3;
void loop(CgalMesh& sm, int levels) { sm3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(levels)); }
void sqrt3(CgalMesh& sm, int levels) { sm3::Sqrt3_subdivision(sm, CGAL::parameters::number_of_iterations(levels)); }
void doo_sabin(CgalMesh& sm, int levels) { sm3::DooSabin_subdivision(sm, CGAL::parameters::number_of_iterations(levels)); }
void catmull_clark(CgalMesh& sm, int levels) {
  sm3::CatmullClark_subdivision(sm, CGAL::parameters::number_of_iterations(levels));
}

SideRun side(Refine refine, int level) {
  return [refine, level](const Mesh& mesh, Timings& t, Refined& out) {
    Stopwatch clock;
    CgalMesh sm;
    build(mesh, sm);
    t.setup = clock.lap();
    refine(sm, level);
    t.topo = clock.lap();
    out.peak_rss_bytes = peak_rss_bytes();
    // Doo-Sabin removes the old faces and vertices; Surface_mesh only marks them, and its
    // counts and ranges skip what is marked.
    out.faces = std::int64_t(sm.number_of_faces());
    out.xyz.reserve(3 * sm.number_of_vertices());
    for (auto v : sm.vertices())
      for (int k = 0; k < 3; ++k) out.xyz.push_back(sm.point(v)[k]);
  };
}

}  // namespace

SideRun cgal_side(const SideRequest& request) {
  if (request.scheme == "loop") return side(loop, request.level);
  if (request.scheme == "sqrt3") return side(sqrt3, request.level);
  if (request.scheme == "doo-sabin") return side(doo_sabin, request.level);
  if (request.scheme == "catmull-clark") return side(catmull_clark, request.level);
  return {};
}

std::string cgal_version() { return CGAL_VERSION_STR; }

}  // namespace subdiv_bench
