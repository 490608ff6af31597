#pragma once
// Where one period of a plugin's primal split (SplitterInfo::period steps; docs/limit.md,
// "Plugins' splits") puts the faces it makes inside a parent face, in that face's (u, v):
// Bfr's quad (0,0), (1,0), (1,1), (0,1) or triangle (0,0), (1,0), (0,1). Every new vertex is
// placed where the split says it comes from: a vertex child at its parent vertex, the i-th of
// c edge children at (i + 1)/(c + 1) along its edge, a face child at the centroid of its
// parent face's corners; in the period's first step, the face point of a neighbour across an
// edge at that neighbour's centroid with the grid unfolded affinely across the edge (for a
// period of 2, whose second step joins the two faces' points). The faces of the period's last
// level whose corners all lie in the face are its children; they must be m x m affine copies
// of it (m the period's scale, 2 or 3), or the split has no nested parameterisation.
//
// Only the elements around the face are visited (children are found through ChildrenOf, the
// inverse of the step's ChildOrigins), so a caller may place every face of a large level.
#include <span>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/limit/face_domain.h"

namespace subdiv {

// The children of each parent element after one step: the inverse of the step's ChildOrigins.
class ChildrenOf {
public:
  ChildrenOf(const Level& parent, const ChildOrigins& origins);
  Index vertex(Index v) const { return vertex_child_[size_t(v)]; }  // kNone when the split drops it
  Index face(Index f) const { return face_child_[size_t(f)]; }      // kNone when the face has no point
  // The edge's children in the order of their `local` index (from the edge's first vertex).
  std::span<const Index> edge(Index e) const {
    return {edge_children_.data() + edge_offset_[size_t(e)], size_t(edge_offset_[size_t(e) + 1] - edge_offset_[size_t(e)])};
  }

private:
  std::vector<Index> vertex_child_, face_child_, edge_offset_, edge_children_;
};

// The faces of h.levels[first + period] inside face f of h.levels[first], with their corners
// in f's frame; `children_of[s]` is ChildrenOf for step first + s. Throws subdiv::Error when
// they are not `factor` x `factor` affine copies of f.
std::vector<ChildFace> period_children(const Hierarchy& h, size_t first, int period, Index f, bool triangles,
                                       int factor, std::span<const ChildrenOf> children_of);

}  // namespace subdiv
