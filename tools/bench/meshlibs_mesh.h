#pragma once
// The base meshes of subdiv-bench-meshlibs: bench_mesh.h's generated tori, chosen by the
// kind of faces a scheme takes, plus a triangle mesh with extraordinary vertices.
#include <cstdint>
#include <string>

#include "bench_mesh.h"

namespace subdiv_bench {

// The mesh a scheme runs on. `extraordinary` false: "tri-torus" (every vertex valence 6)
// for the triangle schemes, "torus" (valence 4) for the others. True: "tri-torus-ev"
// (valences 3 to 8, see the .cpp) for the triangle schemes, "torus-ev" for the others.
std::string mesh_kind_for(const std::string& scheme, bool extraordinary);

// bench_mesh.h's make_mesh, and "tri-torus-ev".
Mesh make_meshlibs_mesh(const std::string& kind, std::int64_t target_faces);

}  // namespace subdiv_bench
