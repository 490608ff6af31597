#pragma once
// The neighbourhoods a descent passes through, each computed once.
//
// A face's neighbourhood (the cut the descent works on) is identified by its canonical
// labelling's signature (analysis/surface/local_patch.h: valences, face sizes, boundary,
// sharpness, in a labelling that depends on the combinatorics only). Two cuts with one
// signature refine alike, so the step from a node to each of its face's children — the
// child's node, the child's corners in the face's coordinates, and the local subdivision
// matrix from the node's labels to the child's (the picking matrices of Stam 1998) — and
// the limit and tangent rows at each corner are computed once, with the engine, and then
// only applied. A regular region has a handful of nodes, so evaluating a point costs a
// sparse matrix-vector product per level.
#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "framework/limit/corner_limit.h"
#include "framework/limit/face_domain.h"
#include "framework/limit/triangle_patch.h"
#include "framework/limit/step_matrix.h"
#include "framework/util/error.h"

namespace subdiv {

// A step or corner read beyond the depth the nodes carry: evaluate again with more rings.
class NotClosed : public Error {
public:
  using Error::Error;
};

struct LimitNode {
  Level level;                    // the cut, as first met
  Index face = kNone;
  std::vector<Index> vertex_of;   // label -> vertex of the cut
  std::vector<Index> label_of;    // vertex of the cut -> label
  Index kept = 0;                 // labels the evaluation carries: those within the depth
  bool expanded = false;
  std::vector<ChildFace> children;  // corners in this face's coordinates
  std::vector<int> child_node;
  std::vector<StepMatrix> child_matrix;  // rows: the child's labels; columns: this node's labels
  // Per child that is this node again (a self-similar step, as towards an extraordinary
  // vertex): the step's powers M^(2^j), each with its derivative forms (2 (M - 1 e_0))^(2^j)
  // and, for second derivatives, (4 (M - 1 e_0))^(2^j).
  using Powers = StepPowers;  // step_matrix.h
  std::vector<std::unique_ptr<Powers>> powers;
  std::vector<char> corner_tried, corner_ready;
  // Bicubic B-spline check (LimitNodes::bspline): 0 not done, 1 yes, 2 no; the labels of the
  // 4 x 4 control points, row by row from (-1, -1) in the face's frame.
  int bspline = 0;
  std::array<Index, 16> grid{};
  // Polynomial patch (triangle_patch.h: quartic over a triangle; tensor_patch.h: degree 4
  // per direction over a quad): 0 not tried, 1 yes, 2 no; the limit rows at the lattice
  // points (i/4, j/4) of the face, and a triangle's box spline labels when it is one.
  int quartic = 0;
  PolynomialPatch patch;
  std::vector<CornerRows> corner;  // over labels
  std::vector<NoLimitMask> corner_error;
};

struct Labelling;
class WeightTableCache;

class LimitNodes {
public:
  // Cuts have `radius` face rings; the evaluation carries the vertices within `depth` rings
  // of the face, which must be closed under the steps (checked as nodes are expanded).
  LimitNodes(const Scheme& scheme, const FeatureOptions& features, int radius, int depth, bool triangles,
             SchemeLimits& limits);
  ~LimitNodes();

  // The node of a cut around `face`, and the cut's vertices the node keeps, in label order.
  int intern(const Level& cut, Index face, std::vector<Index>& order);
  // The node with its children computed.
  const LimitNode& expanded(int id);
  // The rows at the node face's corner k, or null when the vertex is not yet in a
  // configuration the masks describe (`error` then says why when the analysis failed).
  const CornerRows* corner(int id, int k, NoLimitMask& error);
  const LimitNode& node(int id);
  int depth() const { return depth_; }
  // The weight tables the nodes' refinements keep (cut_weight_tables.h), for other cut
  // refinements of the same surface.
  WeightTableCache* weight_tables() const { return tables_.get(); }
  // The powers of child `which`'s step of node `id`, which must lead back to the node.
  // Skipping m levels then costs one product per binary digit of m, whatever m is (powers
  // by squaring, which unlike an eigen-decomposition needs no diagonalisable matrix:
  // picking matrices have defective zero eigenvalues).
  // `count`: the powers M^(2^j), j < count, the caller reads (made on first use; `second`:
  // with their second-derivative forms).
  const LimitNode::Powers& powers(int id, int which, int count, bool second);
  static constexpr int kPowers = 11;  // 2^11 levels: below the smallest double

  // The control points' labels when the limit over the node's face is the uniform bicubic
  // B-spline patch of its 4 x 4 carried points, else null. Decided from the scheme's own
  // rows, never its name: every node the face's refinements lead to (the node itself, in
  // a regular region) must carry a 4 x 4 grid and refine it by the B-spline rules (Lane &
  // Riesenfeld 1980: 1/8 (1, 6, 1) at the old points, 1/2 (1, 1) between them, in each
  // direction). The limit is then the patch (de Boor), evaluated in closed form.
  const std::array<Index, 16>* bspline(int id);

  // The quartic triangle patch of node `id`, once decided: null when not tried yet (then
  // `try_quartic` says so, and the caller samples the rows and calls set_quartic) or not one.
  const PolynomialPatch* quartic(int id, bool& untried);
  void set_quartic(int id, PolynomialPatch patch);  // an empty lattice: not one

private:
  LimitNode& expand_locked(int id);
  const std::array<Index, 16>* bspline_isolated(int id);
  const CornerRows* corner_isolated(int id, int k, NoLimitMask& error);
  bool grid_locked(LimitNode& n);
  bool bspline_step_locked(int id);
  int intern_locked(const Level& cut, Index face, std::vector<Index>& order);
  int intern_labelled(const Level& cut, Index face, const Labelling& lab, std::vector<Index>& order);

  const Scheme& scheme_;
  FeatureOptions features_;
  int radius_, depth_;
  bool triangles_;
  SchemeLimits& limits_;
  std::unique_ptr<WeightTableCache> tables_;  // cut_weight_tables.h
  std::mutex mutex_;
  std::map<std::vector<double>, int> index_;
  std::vector<std::unique_ptr<LimitNode>> nodes_;
};

}  // namespace subdiv
