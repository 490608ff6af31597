#include "memory_guard.h"

#include <fmt/format.h>
#include <fstream>
#include <string>

#include "framework/util/error.h"
#include "framework/util/memory_limit.h"

namespace subdiv::cli {
namespace {

// Bytes per face of the finest level kept by a refinement: topology (faces, edges,
// rings), the stencil table and positions, measured at about 250 B on quad meshes.
constexpr double kBytesPerFace = 300.0;

}  // namespace

double available_memory_bytes() { return available_memory().bytes; }

void check_fits_in_memory(const Scheme& scheme, const Level& base, int levels) {
  // A quad split turns the corners of a level into faces, then each quad into 4.
  double faces = base.face_count();
  for (int l = 0; l < levels; ++l)
    faces = scheme.split() == SplitKind::Quad && l == 0 ? double(base.corner_count()) : 4.0 * faces;
  const MemoryBudget have = available_memory();
  const double need = faces * kBytesPerFace;
  if (need > have.bytes)
    throw Error(fmt::format("{} levels would make about {:.3g} faces and need about {:.1f} GiB, but "
                            "only {:.1f} GiB of memory is available (limited by {}); ask for fewer levels",
                            levels, faces, need / (1 << 30), have.bytes / (1 << 30), have.source));
}

}  // namespace subdiv::cli
