#include "meshlibs_mesh.h"

namespace subdiv_bench {

std::string mesh_kind_for(const std::string& scheme, bool extraordinary) {
  const bool triangles = scheme == "loop" || scheme == "sqrt3" || scheme == "modified-butterfly";
  if (triangles) return extraordinary ? "tri-torus-ev" : "tri-torus";
  return extraordinary ? "torus-ev" : "torus";
}

namespace {

// "torus-ev" (valence 6 grid vertices, valence 3 centres, valence 4 edge midpoints, all in
// quads) with each quad cut into two triangles: mostly along the diagonal between the two
// edge midpoints, along the other one (grid vertex to centre) for three quads in every
// twelve (two grid cells' worth). The pattern was chosen by counting: it gives valences 3,
// 4, 5, 6, 7 and 8, so the check meets every case of the modified butterfly's s_j (3, 4,
// >= 5) and Loop's and sqrt3's extraordinary weights.
Mesh make_tri_torus_ev(std::int64_t target_faces) {
  const Mesh quads = make_mesh("torus-ev", (target_faces + 1) / 2);
  Mesh m;
  m.name = "tri-torus-ev";
  m.vertex_count = quads.vertex_count;
  m.xyz = quads.xyz;
  m.face_offsets.reserve(2 * size_t(quads.face_count()) + 1);
  m.face_sizes.assign(2 * size_t(quads.face_count()), 3);
  m.face_vertices.reserve(6 * size_t(quads.face_count()));
  for (std::int32_t f = 0; f < quads.face_count(); ++f) {
    const std::int32_t* q = &quads.face_vertices[size_t(quads.face_offsets[f])];
    const int s = (f % 12 < 2 || f % 12 == 7) ? 0 : 1;  // the diagonal from corner s to corner s + 2
    for (std::int32_t v : {q[s], q[s + 1], q[(s + 2) % 4], q[s], q[(s + 2) % 4], q[(s + 3) % 4]})
      m.face_vertices.push_back(v);
    m.face_offsets.push_back(m.face_offsets.back() + 3);
    m.face_offsets.push_back(m.face_offsets.back() + 3);
  }
  return m;
}

}  // namespace

Mesh make_meshlibs_mesh(const std::string& kind, std::int64_t target_faces) {
  if (kind == "tri-torus-ev") return make_tri_torus_ev(target_faces);
  return make_mesh(kind, target_faces);
}

}  // namespace subdiv_bench
