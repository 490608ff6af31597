#include "framework/limit/sequence_head.h"

#include <fmt/format.h>

#include "framework/limit/dual_limit.h"
#include "framework/limit/sqrt3_pair_children.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

std::string sequence_head_unsupported(const Scheme& scheme) {
  if (!scheme.linear())
    return fmt::format("{} has non-linear rules: the sequence's limit is no fixed combination of the control points",
                       subdiv::quoted(scheme.name));
  const SplitKind split = scheme.split();
  if (split != SplitKind::Quad && split != SplitKind::Triangle && split != SplitKind::Dual &&
      split != SplitKind::Sqrt3)
    return fmt::format("{} comes before the scheme that repeats and its split is not the binary quad, triangle, "
                       "sqrt3 or dual split: following a point through a mid-edge or plugin split in a sequence's "
                       "head is not implemented yet",
                       subdiv::quoted(scheme.name));
  return {};
}

namespace {

bool has_feature_edges(const Level& L) {
  for (Index e = 0; e < L.edge_count(); ++e)
    if (L.edge_on_boundary(e) || L.edge_sharp(e) > 0.f) return true;
  return false;
}

}  // namespace

std::string sequence_tail_unsupported(const Scheme& tail, const SequenceHead& head) {
  if (tail.split() != SplitKind::Sqrt3 || head.levels() % 2 == 0) return {};
  const Level& mesh = head.refined();
  for (Index e = 0; e < mesh.edge_count(); ++e)
    if (mesh.edge_on_boundary(e) || mesh.edge_sharp(e) > 0.f)
      return fmt::format("{} repeats after {} level(s) of the sequence's head, an odd number, and the mesh they make "
                         "has boundaries or creases: the sqrt3 split trisects those in every second step counted from "
                         "the base mesh, so its first step here trisects, and its evaluation follows the split two "
                         "steps at a time from a step that does not; give the head an even number of levels",
                         subdiv::quoted(tail.name), head.levels());
  return {};
}

SequenceHead::SequenceHead(std::vector<LimitHeadRun> runs, const Level& base, const FeatureOptions& features)
    : runs_(std::move(runs)) {
  std::vector<SchemeRun> plain;
  for (const LimitHeadRun& r : runs_) {
    if (!r.scheme) throw Error("no scheme given for a run of the sequence");
    if (const std::string why = sequence_head_unsupported(*r.scheme); !why.empty()) throw Error(why);
    if (r.levels <= 0) continue;
    plain.push_back({r.scheme.get(), r.levels});
    for (int l = 0; l < r.levels; ++l) {
      const SplitKind split = r.scheme->split();
      triangles_.push_back(split == SplitKind::Triangle || split == SplitKind::Sqrt3 ? 1 : 0);
      dual_.push_back(split == SplitKind::Dual ? 1 : 0);
      sqrt3_.push_back(split == SplitKind::Sqrt3 ? 1 : 0);
    }
  }
  if (plain.empty()) throw Error("the sequence's head has no levels");
  for (size_t l = 0; l < dual_.size(); ++l) {
    if (!dual_[l]) continue;
    if (l > 0 && triangles_[l - 1])
      throw Error("the sequence's head has a dual split after a triangle split: following a point from a triangle's "
                  "own (u, v) into quadrants is not implemented yet");
    if (const std::string why = dual_head_unsupported(base); !why.empty())
      throw Error("the sequence's head has a dual split and " + why);
  }
  RefineOptions ro;
  ro.features = features;
  hierarchy_ = refine(std::span<const SchemeRun>(plain), base, ro);
  if (!hierarchy_.linear()) throw Error("the sequence's head has non-linear steps: no limit stencil exists");
  pair_sqrt3_steps();
}

// sqrt3 steps are followed two at a time, a pair being the triadic split of each triangle
// when its first step keeps the boundaries and creases (an even step counted from the base
// mesh, as refinement counts it) or the level has none (then every step is the same).
void SequenceHead::pair_sqrt3_steps() {
  pair_children_.resize(sqrt3_.size());
  for (size_t l = 0; l < sqrt3_.size(); ++l) {
    if (!sqrt3_[l]) continue;
    const Level& parent = hierarchy_.levels[l];
    if (l + 1 == sqrt3_.size() || !sqrt3_[l + 1])
      throw Error(fmt::format("the sequence's head ends a run of sqrt3 steps at level {} after an odd number of them: "
                              "one sqrt3 step flips the edges, so its triangles are not parts of the faces before it; "
                              "a point is followed through sqrt3 two steps at a time (together the triadic 1-to-9 "
                              "split); give the head's sqrt3 an even number of levels",
                              l + 1));
    if (l % 2 == 1 && has_feature_edges(parent))
      throw Error(fmt::format("the sequence's head starts a pair of sqrt3 steps at level {}, an odd step, on a mesh "
                              "with boundaries or creases: the sqrt3 split trisects those in every second step "
                              "counted from the base mesh, so this pair is not the triadic split of the faces before "
                              "it; give the schemes before the sqrt3 an even number of levels",
                              l));
    pair_children_[l] = sqrt3_pair_children(parent, hierarchy_.levels[l + 1], hierarchy_.levels[l + 2],
                                            hierarchy_.origins[l], hierarchy_.origins[l + 1]);
    for (Index f = 0; f < parent.face_count(); ++f)
      if (!parent.is_hole(f) && pair_children_[l][size_t(f)].size() != 9)
        throw Error(fmt::format("the sequence's head: face {} of level {} is not split into the nine triangles of its "
                                "triadic grid by two sqrt3 steps ({} found): a point in it cannot be followed",
                                f, l, pair_children_[l][size_t(f)].size()));
    ++l;  // the pair's second step
  }
}

FacePoint SequenceHead::map(const Level& base, Index face, double u, double v) const {
  const char* why = "";
  auto p = base_face_point(base, face, u, v, triangles(), &why);
  if (!p) throw Error(fmt::format("face {} at (u, v) = ({}, {}): {}", face, u, v, why));
  for (size_t l = 0; l < hierarchy_.origins.size(); ++l) {
    if (sqrt3_[l]) {
      p = locate(pair_children_[l][size_t(p->face)], *p, true, nullptr);
      ++l;  // two steps at once
    } else if (dual_[l]) {
      p = dual_child_point(hierarchy_.levels[l], hierarchy_.levels[l + 1], hierarchy_.origins[l], *p);
    } else {
      p = child_face_point(hierarchy_.levels[l], hierarchy_.levels[l + 1], hierarchy_.origins[l], *p,
                           triangles_[l] != 0);
    }
    if (!p) throw Error(fmt::format("internal: no face of level {} of the sequence's head holds the point", l + 1));
  }
  if (p->sub_face >= 0) {  // the face's own (u, v): Bfr's tile of the sub-face
    const int columns = sub_face_columns(refined().face_size(p->face));
    p->st = {p->sub_face % columns + 0.5 * p->st[0], p->sub_face / columns + 0.5 * p->st[1]};
    for (auto& row : p->jacobian)
      for (double& x : row) x *= 0.5;
    p->sub_face = -1;
  }
  return *p;
}

SparseRow SequenceHead::pull_back(SparseRow row) const {
  normalise_row(row);
  for (size_t l = hierarchy_.stencils.size(); l-- > 0;) row = subdiv::pull_back(row, hierarchy_.stencils[l]);
  return row;
}

}  // namespace subdiv
