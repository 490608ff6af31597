// README's "As a library" program against the installed package: read a mesh, load a
// built-in scheme by name, refine two levels, carry the points. Checks the counts of
// Catmull-Clark on a closed quad mesh: each level makes V + E + F vertices and 4F quads
// (Catmull & Clark 1978), so the cube (8, 12, 6) has 98 vertices and 96 faces at level 2.
#include <cstdio>

#include "framework/engine/refiner.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: uses_subdiv MESH\n");
    return 2;
  }
  try {
    const subdiv::MeshData mesh = subdiv::read_mesh(argv[1]);
    const auto scheme = subdiv::load_scheme("catmull-clark");
    subdiv::RefineOptions options;
    options.levels = 2;
    const subdiv::Hierarchy h = subdiv::refine(*scheme, subdiv::level_from_mesh(mesh, argv[1]), options);
    const std::vector<double> p = subdiv::interpolate(h, 2, mesh.positions, 3);
    const int faces = h.levels.back().face_count();
    std::printf("uses_subdiv: %zu points, %d faces at level 2\n", p.size() / 3, faces);
    return p.size() == 3 * 98 && faces == 96 ? 0 : 1;
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "uses_subdiv: %s\n", e.what());
    return 1;
  }
}
