#pragma once
// The neighbourhoods a mid-edge descent passes through (mid_edge_limit.h), each worked out
// once: as for √3 (sqrt3_nodes.h), a cut around a face is identified by its canonical
// labelling's signature, refined two steps with the engine on the cut renumbered by its labels,
// and the two steps written as one dual step (mid_edge_double_origins); the child a point moves
// into (dual_child_point) gets its node and its matrix from this node's labels on first use,
// and the limit and tangent rows at the face's centre are computed once. A point then costs a
// sparse product per double step.
#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "framework/engine/refiner.h"
#include "framework/limit/step_matrix.h"

namespace subdiv {

struct Scheme;
class SchemeLimits;
class WeightTableCache;

struct MidEdgeNode {
  Level level;  // the cut, its vertices numbered by their labels
  Index face = kNone;
  bool expanded = false;
  Hierarchy steps;       // two steps of the cut
  ChildOrigins origins;  // of level 2, as those of one dual step
  struct Child {
    int node = -1;
    StepMatrix matrix;  // rows: the child's labels; columns: this node's labels
  };
  std::map<Index, Child> children;  // by face of level 2, made on first use
  // The face's centre: 0 not tried, 1 its limit mask applies, 2 not yet (irregular near).
  int centre_state = 0;
  std::vector<double> position, ds, dt;  // over labels; ds, dt empty where no tangents
  // Per corner of the face: the 3 x 3 labels around it where the four-direction box spline
  // applies to its quadrant (four_direction_patch.h); 0 not tried, 1 it applies, 2 not.
  std::array<int, 4> grid_state{};
  std::array<std::array<Index, 9>, 4> grid{};
};

class MidEdgeNodes {
public:
  MidEdgeNodes(const Scheme& scheme, const FeatureOptions& features, int radius, SchemeLimits& limits);
  ~MidEdgeNodes();

  // The node of a cut around `face`, and the cut's vertices in label order.
  int intern(const Level& cut, Index face, std::vector<Index>& order);
  // The node with its two steps computed (those fields do not change afterwards).
  const MidEdgeNode& expanded(int id);
  // The child of node `id` around face `g` of its level 2.
  const MidEdgeNode::Child& child(int id, Index g);
  // The node's rows at its face's centre, or null where its neighbourhood is not yet the
  // mask's (`error` says why when the analysis has no mask).
  const MidEdgeNode* centre(int id, std::string& error);
  // The 3 x 3 labels around corner `corner` of the node's face (a quad) when the grid there is
  // regular enough for the four-direction box spline (mid_edge_nodes.cpp says what), or null.
  const std::array<Index, 9>* quadrant_grid(int id, int corner);

private:
  int intern_locked(const Level& cut, Index face, std::vector<Index>& order);

  const Scheme& scheme_;
  FeatureOptions features_;
  int radius_;
  SchemeLimits& limits_;
  std::unique_ptr<WeightTableCache> tables_;  // cut_weight_tables.h
  std::mutex mutex_;
  std::map<std::vector<double>, int> index_;
  std::vector<std::unique_ptr<MidEdgeNode>> nodes_;
};

}  // namespace subdiv
