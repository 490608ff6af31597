#pragma once
// Topology rules: each splitter maps a parent Level to a child Level and records where
// every child vertex came from. Child vertices are numbered by origin in blocks:
// children of parent vertices, then of edges, then of faces (then of face corners),
// each block in parent index order.
#include <string_view>

#include "framework/refine/child_origins.h"
#include "framework/topology/level.h"

namespace subdiv {

struct SplitResult {
  Level child;
  ChildOrigins origins;
};

// Primal 1-to-k split of any polygon: a k-gon becomes k quads around a new face point.
SplitResult split_quad(const Level& parent);
// Primal 1-to-4 split of triangles; the caller checks that all faces are triangles.
SplitResult split_triangle(const Level& parent);

enum class SplitKind { Quad, Triangle };
SplitResult split(SplitKind kind, const Level& parent);
// "quad" / "triangle"; throws for unknown names.
SplitKind split_kind_from_name(std::string_view name);

}  // namespace subdiv
