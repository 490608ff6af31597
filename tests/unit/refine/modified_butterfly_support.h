#pragma once
// What the modified butterfly boundary and sector tests share: a point of an xyz array, the
// child of a parent edge, and `levels` steps of modified-butterfly on a level with positions.
#include <doctest/doctest.h>

#include <array>

#include "support/refine_helpers.h"

namespace subdiv::test {

using Point = std::array<double, 3>;

inline Point at(const std::vector<double>& xyz, Index v) { return {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]}; }

struct OneLevel {
  Hierarchy h;
  std::vector<double> positions;  // at the finest level
};

inline OneLevel refine_level(const Level& base, const std::vector<double>& positions, int levels = 1) {
  RefineOptions o;
  o.levels = levels;
  OneLevel r{refine(*load_scheme("modified-butterfly"), base, o), {}};
  r.positions = interpolate(r.h, levels, positions, 3);
  return r;
}

// The child of parent edge e after one step.
inline Index edge_child(const ChildOrigins& origins, Index e) {
  for (Index c = 0; c < Index(origins.kind.size()); ++c)
    if (origins.kind[c] == OriginKind::Edge && origins.parent[c] == e) return c;
  FAIL("edge has no child");
  return kNone;
}

}  // namespace subdiv::test
