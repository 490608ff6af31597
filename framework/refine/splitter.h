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
  // False when this step leaves boundaries and creases unrefined (odd sqrt3 steps):
  // their vertices then stay where they are.
  bool features_refined = true;
};

// Primal 1-to-k split of any polygon: a k-gon becomes k quads around a new face point.
SplitResult split_quad(const Level& parent);
// Primal 1-to-4 split of triangles; the caller checks that all faces are triangles.
SplitResult split_triangle(const Level& parent);

// sqrt(3) (Kobbelt 2000): one new point per face, old edges flipped; boundaries and sharp
// edges are trisected every second step (step_index odd, counted from 0 at the input).
SplitResult split_sqrt3(const Level& parent, int step_index);
// Dual (Doo-Sabin): one new point per face corner; F-faces, E-faces (interior edges) and
// V-faces (interior vertices, and boundary vertices with three or more faces).
SplitResult split_dual(const Level& parent);
// Mid-edge (Peters-Reif 1997): one new point per edge; F-faces and V-faces.
SplitResult split_mid_edge(const Level& parent);

enum class SplitKind { Quad, Triangle, Sqrt3, Dual, MidEdge };
SplitResult split(SplitKind kind, const Level& parent, int step_index);
// "quad", "triangle", "sqrt3", "dual", "mid-edge"; throws for unknown names.
SplitKind split_kind_from_name(std::string_view name);

}  // namespace subdiv
