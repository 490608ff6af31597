#pragma once
// subdiv-bench-meshlibs: the three libraries behind one signature. Each side builds its
// own mesh structure from the generated mesh (timed as setup), refines it `level` times
// with its own subdivider (timed as refine), and hands back the refined positions and
// face count, read off its structure after the clock stopped.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bench_common.h"

namespace subdiv_bench {

struct Refined {
  std::vector<double> xyz;  // 3 doubles per vertex, in the side's own vertex order
  std::int64_t faces = 0;
  // Peak RSS read right after the refinement, before `xyz` is copied out of OpenMesh's or
  // CGAL's mesh (SubdivKit's result is `xyz` itself, moved in).
  std::int64_t peak_rss_bytes = 0;
  // SubdivKit: new points computed by the compiled kernels, by learnt row plans and by the
  // generic rule interpreter (rules/row_paths.h), which says where its time goes.
  std::int64_t kernel_points = 0, plan_points = 0, generic_points = 0, flat_points = 0;  // flat: of the kernel points
};

// Scheme names are SubdivKit's (schemes/*.json): sqrt3, doo-sabin, modified-butterfly,
// loop, catmull-clark. `last_level_full`: SubdivKit builds the last level's edges and
// vertex rings too (as OpenMesh and CGAL always do: their result is a halfedge mesh);
// false gives the last level's faces only (RefineOptions::faces_only_last_level).
struct SideRequest {
  std::string scheme;
  int level = 1;
  bool last_level_full = true;
};

// One refinement, timed into t.setup and t.topo (OpenMesh and CGAL refine topology and
// geometry in one pass; SubdivKit's geometry goes into t.apply), then `out` filled in
// after the clock stopped.
using SideRun = std::function<void(const Mesh& mesh, Timings& t, Refined& out)>;

// Empty when the library was not found at build time or has no subdivider for the scheme.
// Whatever a library does once per program (SubdivKit: loading the scheme file) is done
// here, outside the timed runs.
SideRun subdivkit_side(const SideRequest& request);
SideRun openmesh_side(const SideRequest& request);
SideRun cgal_side(const SideRequest& request);

// "x.y.z" of the library found at build time, or "none".
std::string openmesh_version();
std::string cgal_version();

}  // namespace subdiv_bench
