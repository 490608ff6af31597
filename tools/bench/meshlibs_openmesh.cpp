// subdiv-bench-meshlibs, OpenMesh's side: its uniform subdividers
// (OpenMesh/Tools/Subdivider/Uniform) on its array-kernel meshes, as OpenMesh's own
// examples use them: build the mesh, then `Subdivider()(mesh, levels)`.
//
// Positions are doubles (Vec3d traits), as SubdivKit's, so that the check compares the
// schemes and not float round-off. The triangle subdividers (Loop, sqrt3, modified
// butterfly) need a TriMesh, Catmull-Clark a PolyMesh. OpenMesh has no Doo-Sabin.
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/config.h>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/ModifiedButterFlyT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>

#include "meshlibs_sides.h"

namespace subdiv_bench {
namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OmTriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using OmPolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

template <class OmMesh>
void build(const Mesh& mesh, OmMesh& om) {
  om.reserve(size_t(mesh.vertex_count), mesh.face_vertices.size() / 2, size_t(mesh.face_count()));
  for (std::int32_t v = 0; v < mesh.vertex_count; ++v)
    om.add_vertex(typename OmMesh::Point(mesh.xyz[3 * size_t(v)], mesh.xyz[3 * size_t(v) + 1], mesh.xyz[3 * size_t(v) + 2]));
  std::vector<OpenMesh::VertexHandle> corners;
  for (std::int32_t f = 0; f < mesh.face_count(); ++f) {
    corners.clear();
    for (std::int32_t i = mesh.face_offsets[f]; i < mesh.face_offsets[f + 1]; ++i)
      corners.emplace_back(mesh.face_vertices[size_t(i)]);
    om.add_face(corners);
  }
}

template <class OmMesh, template <class, class> class Subdivider>
SideRun side(int level) {
  return [level](const Mesh& mesh, Timings& t, Refined& out) {
    Stopwatch clock;
    OmMesh om;
    build(mesh, om);
    t.setup = clock.lap();
    Subdivider<OmMesh, double> subdivider;
    subdivider(om, size_t(level));
    t.topo = clock.lap();
    out.peak_rss_bytes = peak_rss_bytes();
    out.faces = std::int64_t(om.n_faces());
    out.xyz.reserve(3 * om.n_vertices());
    for (auto v : om.vertices())
      for (int k = 0; k < 3; ++k) out.xyz.push_back(om.point(v)[k]);
  };
}

}  // namespace

SideRun openmesh_side(const SideRequest& request) {
  using namespace OpenMesh::Subdivider::Uniform;
  if (request.scheme == "loop") return side<OmTriMesh, LoopT>(request.level);
  if (request.scheme == "sqrt3") return side<OmTriMesh, Sqrt3T>(request.level);
  if (request.scheme == "modified-butterfly") return side<OmTriMesh, ModifiedButterflyT>(request.level);
  if (request.scheme == "catmull-clark") return side<OmPolyMesh, CatmullClarkT>(request.level);
  return {};
}

std::string openmesh_version() {
  return std::to_string(OM_GET_VER) + "." + std::to_string(OM_GET_MAJ) + "." + std::to_string(OM_GET_MIN);
}

}  // namespace subdiv_bench
