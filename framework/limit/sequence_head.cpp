#include "framework/limit/sequence_head.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "framework/limit/dual_limit.h"
#include "framework/limit/mid_edge_limit.h"
#include "framework/limit/mid_edge_pair.h"
#include "framework/limit/plugin_period_children.h"
#include "framework/limit/plugin_split_limit.h"
#include "framework/limit/sqrt3_step_children.h"
#include "framework/refine/splitter.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

std::string sequence_head_unsupported(const Scheme& scheme) {
  if (!scheme.linear())
    return fmt::format("{} has non-linear rules: the sequence's limit is no fixed combination of the control points",
                       subdiv::quoted(scheme.name));
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
      mid_edge_.push_back(split == SplitKind::MidEdge ? 1 : 0);
      plugin_.push_back(split >= SplitKind(kFirstRegisteredSplit) ? 1 : 0);
    }
    if (r.scheme->split() >= SplitKind(kFirstRegisteredSplit)) {
      const SplitterInfo& info = splitter_info(r.scheme->split());
      if (info.period > 1 && r.levels % info.period != 0)
        throw Error(fmt::format("the sequence's head has {} level(s) of {}, whose split {} nests in the faces only "
                                "after every {} steps; give it a multiple of {} levels",
                                r.levels, subdiv::quoted(r.scheme->name), subdiv::quoted(info.name), info.period,
                                info.period));
    }
    if (r.scheme->split() == SplitKind::MidEdge && r.levels % 2 == 1)
      throw Error(fmt::format("the sequence's head has {} level(s) of {}, an odd number: one mid-edge step turns the "
                              "faces by 45 degrees across the old edges, two nest as a dual step does; give it an "
                              "even number of levels",
                              r.levels, subdiv::quoted(r.scheme->name)));
  }
  if (plain.empty()) throw Error("the sequence's head has no levels");
  for (size_t l = 0; l < dual_.size(); ++l) {
    if (!dual_[l] && !mid_edge_[l]) continue;
    if (l > 0 && triangles_[l - 1])
      throw Error("the sequence's head has a dual or mid-edge split after a triangle split: following a point from a "
                  "triangle's own (u, v) into quadrants is not implemented yet");
    if (!dual_[l]) continue;
    if (const std::string why = dual_head_unsupported(base); !why.empty())
      throw Error("the sequence's head has a dual split and " + why);
  }
  RefineOptions ro;
  ro.features = features;
  hierarchy_ = refine(std::span<const SchemeRun>(plain), base, ro);
  if (!hierarchy_.linear()) throw Error("the sequence's head has non-linear steps: no limit stencil exists");
  place_sqrt3_children();
  pair_mid_edge_steps();
  place_plugin_children();
}

// A plugin's split one period at a time (plugin_period_children.h), on the meshes its own
// evaluation takes (closed, all quads or all triangles, no creases: plugin_split_limit.h).
void SequenceHead::place_plugin_children() {
  plugin_children_.resize(plugin_.size());
  plugin_period_.assign(plugin_.size(), 0);
  size_t run_start = 0;
  for (const LimitHeadRun& r : runs_) {
    const int levels = std::max(r.levels, 0);
    const bool plugin = levels > 0 && plugin_[run_start];
    const SplitterInfo* info = plugin ? &splitter_info(r.scheme->split()) : nullptr;
    const int period = plugin ? info->period : 1;
    const int factor = plugin ? int(std::lround(std::pow(info->scale, info->period))) : 1;
    for (size_t l = run_start; plugin && l < run_start + size_t(levels); l += size_t(period)) {
      const Level& parent = hierarchy_.levels[l];
      if (const std::string why = plugin_split_limit_unsupported(*r.scheme, parent); !why.empty())
        throw Error(fmt::format("the sequence's head, at level {}: {}", l, why));
      const bool triangles = parent.all_faces_have_size(3);
      for (int s = 0; s < period; ++s) triangles_[l + size_t(s)] = triangles ? 1 : 0;
      std::vector<ChildrenOf> children_of;
      for (int s = 0; s < period; ++s) children_of.emplace_back(hierarchy_.levels[l + size_t(s)], hierarchy_.origins[l + size_t(s)]);
      plugin_period_[l] = period;
      plugin_children_[l].resize(size_t(parent.face_count()));
      for (Index f = 0; f < parent.face_count(); ++f)
        plugin_children_[l][size_t(f)] = period_children(hierarchy_, l, period, f, triangles, factor, children_of);
    }
    run_start += size_t(levels);
  }
}

// Two mid-edge steps nest as one dual step (mid_edge_pair.h), on closed meshes without creases.
void SequenceHead::pair_mid_edge_steps() {
  mid_edge_origins_.resize(mid_edge_.size());
  for (size_t l = 0; l < mid_edge_.size(); ++l) {
    if (!mid_edge_[l]) continue;
    if (const std::string why = mid_edge_limit_unsupported(hierarchy_.levels[l]); !why.empty())
      throw Error(fmt::format("the sequence's head has a mid-edge split and at level {} {}", l, why));
    mid_edge_origins_[l] = mid_edge_pair_origins(hierarchy_.levels[l], hierarchy_.levels[l + 1],
                                                 hierarchy_.levels[l + 2], hierarchy_.origins[l],
                                                 hierarchy_.origins[l + 1]);
    ++l;  // the pair's second step
  }
}

namespace {

bool has_feature_edges(const Level& L) {
  for (Index e = 0; e < L.edge_count(); ++e)
    if (L.edge_on_boundary(e) || L.edge_sharp(e) > 0.f) return true;
  return false;
}

bool split_in_nine(const Level& parent, const std::vector<std::vector<ChildFace>>& children) {
  for (Index f = 0; f < parent.face_count(); ++f)
    if (!parent.is_hole(f) && children[size_t(f)].size() != 9) return false;
  return true;
}

}  // namespace

// sqrt3 steps two at a time where the pair is the triadic split (its first step keeps the
// boundaries and creases: an even step counted from the base mesh, as refinement counts it,
// or a level without them), one at a time elsewhere (sqrt3_step_children.h).
void SequenceHead::place_sqrt3_children() {
  sqrt3_children_.resize(sqrt3_.size());
  sqrt3_pair_.assign(sqrt3_.size(), 0);
  for (size_t l = 0; l < sqrt3_.size(); ++l) {
    if (!sqrt3_[l]) continue;
    const Level& parent = hierarchy_.levels[l];
    if (l + 1 < sqrt3_.size() && sqrt3_[l + 1] && (l % 2 == 0 || !has_feature_edges(parent))) {
      auto nine = sqrt3_pair_children(parent, hierarchy_.levels[l + 1], hierarchy_.levels[l + 2],
                                      hierarchy_.origins[l], hierarchy_.origins[l + 1]);
      if (split_in_nine(parent, nine)) {
        sqrt3_children_[l] = std::move(nine);
        sqrt3_pair_[l] = 1;
        ++l;  // the pair's second step
        continue;
      }
    }
    sqrt3_children_[l] = sqrt3_step_children(parent, hierarchy_.levels[l + 1], hierarchy_.origins[l]);
  }
}

FacePoint SequenceHead::map(const Level& base, Index face, double u, double v) const {
  const char* why = "";
  auto p = base_face_point(base, face, u, v, triangles(), &why);
  if (!p) throw Error(fmt::format("face {} at (u, v) = ({}, {}): {}", face, u, v, why));
  for (size_t l = 0; l < hierarchy_.origins.size(); ++l) {
    if (sqrt3_[l]) {
      p = locate(sqrt3_children_[l][size_t(p->face)], *p, true, nullptr);
      if (sqrt3_pair_[l]) ++l;  // two steps at once
      if (!p)
        throw Error(fmt::format("the sequence's head: no triangle of its sqrt3 step to level {} holds the point (a "
                                "face whose new triangles could not be placed in its (u, v): a degenerate "
                                "neighbourhood)",
                                l + 1));
    } else if (plugin_[l]) {
      p = locate(plugin_children_[l][size_t(p->face)], *p, triangles_[l] != 0, nullptr);
      l += size_t(plugin_period_[l]) - 1;  // the period's other steps
      if (!p) throw Error(fmt::format("internal: no face of the plugin's split to level {} holds the point", l + 1));
    } else if (mid_edge_[l]) {
      p = dual_child_point(hierarchy_.levels[l], hierarchy_.levels[l + 2], mid_edge_origins_[l], *p);
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
