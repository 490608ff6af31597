// Splits by name, for the scheme language.
#include <fmt/format.h>

#include "framework/refine/splitter.h"
#include "framework/util/error.h"

namespace subdiv {

SplitResult split(SplitKind kind, const Level& parent, int step_index) {
  switch (kind) {
    case SplitKind::Quad: return split_quad(parent);
    case SplitKind::Triangle: return split_triangle(parent);
    case SplitKind::Sqrt3: return split_sqrt3(parent, step_index);
    case SplitKind::Dual: return split_dual(parent);
    case SplitKind::MidEdge: return split_mid_edge(parent);
  }
  throw Error("unknown split");
}

SplitKind split_kind_from_name(std::string_view name) {
  if (name == "quad") return SplitKind::Quad;
  if (name == "triangle") return SplitKind::Triangle;
  if (name == "sqrt3") return SplitKind::Sqrt3;
  if (name == "dual") return SplitKind::Dual;
  if (name == "mid-edge") return SplitKind::MidEdge;
  throw Error(fmt::format("unknown split '{}'; the splits are: quad, triangle, sqrt3, dual, mid-edge", name));
}

}  // namespace subdiv
