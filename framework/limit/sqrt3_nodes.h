#pragma once
// The neighbourhoods a √3 descent passes through (sqrt3_limit.h), each worked out once.
//
// As for primal schemes (limit_nodes.h): a cut around a triangle is identified by its
// canonical labelling's signature (analysis/surface/local_patch.h), and for each signature
// the two steps to each of the face's nine triadic children — the child's node, where its
// corners lie on the lattice 3b, and the matrix from this node's labels to the child's — and
// the limit and tangent rows at the face's corners are computed once with the engine, on the
// cut renumbered by its labels (so the numbers do not depend on which cut was met first).
// A region of one configuration (regular, or around one extraordinary vertex) then costs a
// sparse product per double step.
#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "framework/features/feature_options.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/step_matrix.h"

namespace subdiv {

struct Scheme;
class SchemeLimits;
class WeightTableCache;

using Bary = std::array<double, 3>;  // barycentric coordinates from a face's corner 0
using Lattice = std::array<int, 3>;  // 3 b: a point of the triadic lattice (sums to 3)

// A triangle of the triadic split: `up` like the parent (corner m = anchor + e_q[m]), else
// turned by 180 degrees (corner m = anchor - e_q[m]); corners in the child face's own order.
struct TriadicChild {
  bool up = true;
  Lattice anchor{};
  std::array<int, 3> q{};
};

// The point's barycentric coordinates in child t (each one subtraction from 3 b_q, so a small
// coordinate keeps its digits; the largest is then 1 less the other two).
Bary in_child(const TriadicChild& t, const Bary& b);
// d(beta_m)/d(s, t) of the parent, over 3.
std::array<double, 2> child_gradient(const TriadicChild& t, int m);

struct Sqrt3Node {
  Level level;  // the cut, its vertices numbered by their labels
  Index face = kNone;
  bool extraordinary = false;  // a corner of the face is not of valence 6
  // The cut's vertices at their unfolded (s, t) (corner_limit.h) where every vertex within
  // radius - 1 rings of the face is interior, of valence 6 and without sharpness, so that the
  // steps from this node keep sampled affine functions affine (both shipped schemes' regular
  // rules have linear precision); else empty. Second-derivative rows pulled back to this node
  // are made to annihilate them again (sqrt3_limit.cpp).
  std::optional<AffineFrame> affine;  // step_matrix.h
  bool expanded = false;
  std::vector<TriadicChild> children;
  std::vector<int> child_node;
  std::vector<StepMatrix> child_matrix;  // rows: the child's labels; columns: this node's labels
  // Per child that is this node again (a self-similar step, towards a vertex): the step's
  // powers M^(2^j), each with its derivative forms (3 (M - 1 e_0))^(2^j) and, once asked
  // for, (9 (M - M Pi))^(2^j) where `affine` is set, else (9 (M - 1 e_0))^(2^j)
  // (step_matrix.h).
  using Powers = StepPowers;  // step_matrix.h
  std::vector<std::unique_ptr<Powers>> powers;
  std::array<int, 3> corner_state{};     // 0 not tried, 1 ready, 2 not a known configuration
  std::array<CornerRows, 3> corner;      // over labels
  std::array<NoLimitMask, 3> corner_error;
  // Per corner: its derivatives were taken away for a boundary a few rings off, and the
  // corner itself is not on it (a deeper level has them).
  std::array<char, 3> corner_deferred{};
};

class Sqrt3Nodes {
public:
  // Cuts have `radius` face rings around their face.
  Sqrt3Nodes(const Scheme& scheme, const FeatureOptions& features, int radius, SchemeLimits& limits);
  ~Sqrt3Nodes();

  // The node of a cut around `face`, and the cut's vertices in label order.
  int intern(const Level& cut, Index face, std::vector<Index>& order);
  // The node with its children computed (its fields do not change afterwards).
  const Sqrt3Node& expanded(int id);
  // The rows at the node face's corner k, or null when the vertex is not yet in a
  // configuration the masks describe (`error` then says why when the analysis failed).
  const CornerRows* corner(int id, int k, NoLimitMask& error);
  // The powers of child `which`'s step of node `id`, which must lead back to the node: m
  // double steps then cost one product per binary digit of m; with `second`, with their
  // second-derivative forms.
  const Sqrt3Node::Powers& powers(int id, int which, bool second);
  static constexpr int kPowers = 10;  // 2^10 double steps: past the smallest double (3^-680)

private:
  int intern_locked(const Level& cut, Index face, std::vector<Index>& order);
  Sqrt3Node& expand_locked(int id);

  const Scheme& scheme_;
  FeatureOptions features_;
  int radius_;
  SchemeLimits& limits_;
  std::unique_ptr<WeightTableCache> tables_;  // cut_weight_tables.h
  std::mutex mutex_;
  std::map<std::vector<double>, int> index_;
  std::vector<std::unique_ptr<Sqrt3Node>> nodes_;
};

}  // namespace subdiv
