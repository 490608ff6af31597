// subdiv-bench-meshlibs without OpenMesh or CGAL: the sides that were not found at build
// time have no subdivider, and the program times what it has.
#include "meshlibs_sides.h"

namespace subdiv_bench {

#ifndef SUBDIV_MESHLIBS_HAVE_OPENMESH
SideRun openmesh_side(const SideRequest&) { return {}; }
std::string openmesh_version() { return "none"; }
#endif

#ifndef SUBDIV_MESHLIBS_HAVE_CGAL
SideRun cgal_side(const SideRequest&) { return {}; }
std::string cgal_version() { return "none"; }
#endif

}  // namespace subdiv_bench
