#pragma once
// The feature context of a point, which picks the rule that moves it (DeRose et al. 1998,
// OpenSubdiv's Sdc::Crease rule masks): by the number of sharp incident edges (0 smooth,
// 1 dart, 2 crease, more: corner) or a sharp vertex (corner). An edge is Smooth or Crease
// (sharp or boundary). Faces are always Smooth. A face corner (dual schemes) is Smooth,
// Crease (one of its two face edges is sharp) or Corner (both are, or its vertex is a corner).
#include <cstdint>

namespace subdiv {

enum class Context : std::uint8_t { Smooth = 0, Dart = 1, Crease = 2, Corner = 3 };
constexpr int kContextCount = 4;

}  // namespace subdiv
