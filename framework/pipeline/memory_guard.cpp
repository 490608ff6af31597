#include "framework/pipeline/memory_guard.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <string>
#include <unistd.h>

#include "framework/util/byte_size_text.h"
#include "framework/util/error.h"
#include "framework/util/memory_limit.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// Bytes per face of the finest level kept by a refinement: topology (faces, edges,
// rings), the stencil table and positions, measured at about 250 B on quad meshes.
constexpr double kBytesPerFace = 300.0;

double finest_faces(const Scheme& scheme, const Level& base, int levels) {
  // A quad split turns the corners of a level into faces, then each quad into 4.
  double faces = base.face_count();
  for (int l = 0; l < levels; ++l)
    faces = scheme.split() == SplitKind::Quad && l == 0 ? double(base.corner_count()) : 4.0 * faces;
  return faces;
}

}  // namespace

double refinement_bytes(const Scheme& scheme, const Level& base, int levels) {
  return finest_faces(scheme, base, levels) * kBytesPerFace;
}

void check_fits_in_memory(const Scheme& scheme, const Level& base, int levels, double limit, const std::string& fix) {
  const MemoryBudget have = memory_budget(limit);
  const double need = refinement_bytes(scheme, base, levels);
  if (need > have.bytes) {
    const auto [need_text, have_text] = byte_sizes_compared(need, have.bytes);
    throw Error(fmt::format("{} levels would make about {:.3g} faces and need about {}, but only {} of memory is "
                            "available (limited by {}); {}",
                            levels, finest_faces(scheme, base, levels), need_text, have_text, have.source, fix));
  }
}

double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0;
  if (!(statm >> size >> resident)) return 0;
  return resident * double(sysconf(_SC_PAGESIZE));
}

double parse_memory_size(const std::string& text, const std::string& option) {
  double number = 0;
  const char* end = text.data() + text.size();
  const auto [rest, ec] = std::from_chars(text.data(), end, number);
  std::string unit(rest, end);
  for (char& c : unit) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (unit.size() == 2 && unit[1] == 'b') unit.resize(1);
  const double scale = unit.empty() ? 1.0 : unit == "k" ? 1024.0 : unit == "m" ? 1024.0 * 1024 : unit == "g" ? 1024.0 * 1024 * 1024 : unit == "t" ? 1024.0 * 1024 * 1024 * 1024 : 0.0;
  if (ec != std::errc() || scale == 0 || !std::isfinite(number) || number <= 0)
    throw Error(fmt::format("{} {} is not a memory size; write it like 8G, 512M or a number of bytes", option,
                            subdiv::quoted(text.substr(0, 40))));
  return number * scale;
}

}  // namespace subdiv
