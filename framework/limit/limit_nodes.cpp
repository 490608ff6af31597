#include "framework/limit/limit_nodes.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <tbb/task_arena.h>

#include "framework/scheme/scheme.h"

#include "framework/analysis/surface/local_patch.h"
#include "framework/engine/refiner.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/limit/canonical_cut.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/cut_weight_tables.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// Hole faces are not in the labelling's signature: each as its corners' labels from the
// smallest, in sorted order.
void append_holes(const Level& cut, const Labelling& lab, std::vector<double>& key) {
  if (cut.face_hole.empty()) return;
  std::vector<std::vector<Index>> holes;
  for (Index f = 0; f < cut.face_count(); ++f) {
    if (!cut.is_hole(f)) continue;
    std::vector<Index> labels;
    for (Index v : cut.face(f)) labels.push_back(lab.label_of[size_t(v)]);
    std::rotate(labels.begin(), std::min_element(labels.begin(), labels.end()), labels.end());
    holes.push_back(std::move(labels));
  }
  std::sort(holes.begin(), holes.end());
  for (const auto& h : holes) {
    key.push_back(-2);
    for (Index l : h) key.push_back(double(l));
  }
}

std::string not_closed(const Scheme& scheme, int depth) {
  return fmt::format("scheme {} reads beyond {} rings of a face while evaluating its limit", subdiv::quoted(scheme.name), depth);
}

// The cut renumbered by its labelling, vertices and faces, so that every cut with one
// signature is the same level, and the engine's weights for it the same bits whichever
// cut was met first (the results do not depend on the order or thread of evaluations).
Level canonical_level(const Level& cut, const Labelling& lab, Index face, Index& canonical_face) {
  std::vector<std::vector<Index>> faces;
  std::vector<Index> original;
  for (Index f = 0; f < cut.face_count(); ++f) {
    std::vector<Index> labels;
    for (Index v : cut.face(f)) labels.push_back(lab.label_of[size_t(v)]);
    const auto first = std::min_element(labels.begin(), labels.end()) - labels.begin();
    std::rotate(labels.begin(), labels.begin() + first, labels.end());
    faces.push_back(std::move(labels));
  }
  std::vector<Index> order(faces.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = Index(i);
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return faces[size_t(a)] < faces[size_t(b)]; });
  std::vector<Index> offsets{0}, corners;
  for (Index f : order) {
    // The centre face keeps its corner 0 first: the point's coordinates are relative to it.
    if (f == face) {
      canonical_face = Index(offsets.size()) - 1;
      for (Index v : cut.face(f)) corners.push_back(lab.label_of[size_t(v)]);
    } else {
      corners.insert(corners.end(), faces[size_t(f)].begin(), faces[size_t(f)].end());
    }
    offsets.push_back(Index(corners.size()));
  }
  Level L = build_level(Index(lab.vertices.size()), offsets, corners);
  carry_sharpness(L, cut, lab);
  if (!cut.face_hole.empty()) {
    L.face_hole.assign(size_t(L.face_count()), 0);
    for (size_t i = 0; i < order.size(); ++i) L.face_hole[i] = cut.face_hole[size_t(order[i])];
  }
  return L;
}

}  // namespace

LimitNodes::LimitNodes(const Scheme& scheme, const FeatureOptions& features, int radius, int depth, bool triangles,
                       SchemeLimits& limits)
    : scheme_(scheme),
      features_(features),
      radius_(radius),
      depth_(depth),
      triangles_(triangles),
      limits_(limits),
      tables_(cut_weight_tables(scheme)) {}

LimitNodes::~LimitNodes() = default;

// Every method that runs the engine (whose loops are parallel) under the lock isolates
// itself: a thread waiting inside those loops must not pick up another evaluation of the
// caller's parallel loop (tessellate), which would lock the same mutex again.
int LimitNodes::intern(const Level& cut, Index face, std::vector<Index>& order) {
  // Labelled before the lock: the labelling is most of a face's preparation and reads no
  // shared state, so parallel preparations wait for each other only on the index.
  // Reused per thread: its arrays (the signature is thousands of values) keep their room.
  thread_local Labelling lab;
  label_neighbourhood(lab, cut, CentreKind::Face, face, 0, radius_ + 3);
  return tbb::this_task_arena::isolate([&] {
    std::lock_guard lock(mutex_);
    return intern_labelled(cut, face, lab, order);
  });
}

int LimitNodes::intern_locked(const Level& cut, Index face, std::vector<Index>& order) {
  return intern_labelled(cut, face, label_neighbourhood(cut, CentreKind::Face, face, 0, radius_ + 3), order);
}

// `lab` is labelled beyond the cut's radius, so every vertex of the cut has a label.
int LimitNodes::intern_labelled(const Level& cut, Index face, const Labelling& lab, std::vector<Index>& order) {
  // A cut grows past its radius only where keeping every vertex manifold takes all faces of
  // pinched vertices again and again (extract_neighbourhood): a thin closed part of the mesh,
  // as two triangles back to back around valence-2 vertices (OpenSubdiv's loop_val2_interior),
  // where each level's cut runs along the whole seam.
  if (lab.vertices.size() != size_t(cut.vertex_count))
    throw Error("the neighbourhood of this point wraps around a part of the mesh thinner than the scheme's "
                "stencils (e.g. two triangles back to back around valence-2 vertices), which limit evaluation does "
                "not take yet; refine the mesh (subdiv refine) and use a level's vertices instead");
  const Index kept = Index(lab.count_within(depth_));
  order.assign(lab.vertices.begin(), lab.vertices.begin() + kept);
  std::vector<double> holed;
  if (!cut.face_hole.empty()) {
    holed = lab.signature;
    append_holes(cut, lab, holed);
  }
  const std::vector<double>& key = cut.face_hole.empty() ? lab.signature : holed;
  // Looked up before it is copied: most cuts meet a node made already.
  if (const auto found = index_.find(key); found != index_.end()) return found->second;
  const auto it = index_.emplace(key, int(nodes_.size())).first;
  auto n = std::make_unique<LimitNode>();
  n->level = canonical_level(cut, lab, face, n->face);
  n->kept = kept;
  n->vertex_of.resize(lab.vertices.size());
  for (size_t l = 0; l < lab.vertices.size(); ++l) n->vertex_of[l] = Index(l);
  n->label_of = n->vertex_of;
  const int k = cut.face_size(face);
  n->corner_tried.assign(size_t(k), 0);
  n->corner_ready.assign(size_t(k), 0);
  n->corner.resize(size_t(k));
  n->corner_error.resize(size_t(k));
  nodes_.push_back(std::move(n));
  return it->second;
}

const LimitNode& LimitNodes::node(int id) {
  std::lock_guard lock(mutex_);
  return *nodes_[size_t(id)];
}

const LimitNode& LimitNodes::expanded(int id) {
  return *tbb::this_task_arena::isolate([&]() -> const LimitNode* {
    std::lock_guard lock(mutex_);
    return &expand_locked(id);
  });
}

LimitNode& LimitNodes::expand_locked(int id) {
  LimitNode* n = nodes_[size_t(id)].get();
  if (n->expanded) return *n;
  RefineOptions ro;
  ro.levels = 1;
  ro.features = features_;
  ro.evaluation.weight_tables = tables_.get();
  const Hierarchy h = refine(scheme_, n->level, ro);
  FacePoint p;
  p.face = n->face;
  n->children = child_faces(n->level, h.levels[1], h.origins[0], p, triangles_);
  const StencilTable& T = h.stencils[0];
  for (const ChildFace& c : n->children) {
    const Extracted e = extract_neighbourhood(h.levels[1], CentreKind::Face, c.face, radius_);
    Index local = kNone;
    for (size_t f = 0; f < e.face_original.size(); ++f)
      if (e.face_original[f] == c.face) local = Index(f);
    std::vector<Index> order;
    const int child = intern_locked(e.level, local, order);
    n = nodes_[size_t(id)].get();
    StepMatrix m;
    m.source_count = n->kept;
    for (Index v : order) {
      const Index r = e.original[size_t(v)];
      for (Index x = T.offsets[size_t(r)]; x < T.offsets[size_t(r) + 1]; ++x) {
        const Index column = n->label_of[size_t(T.indices[size_t(x)])];
        if (column >= n->kept) throw NotClosed(not_closed(scheme_, depth_));
        m.columns.push_back(column);
        m.weights.push_back(T.weights[size_t(x)]);
      }
      m.offsets.push_back(Index(m.columns.size()));
    }
    n->child_node.push_back(child);
    n->powers.emplace_back();
    n->child_matrix.push_back(std::move(m));
  }
  n->expanded = true;
  return *n;
}

const LimitNode::Powers& LimitNodes::powers(int id, int which, int count, bool second) {
  std::lock_guard lock(mutex_);
  LimitNode& n = *nodes_[size_t(id)];
  auto& slot = n.powers[size_t(which)];
  // Binary steps: first-derivative rows scale by 2, second ones by 4 (step_matrix.h).
  if (!slot) slot = lazy_step_powers(n.child_matrix[size_t(which)], 2, kPowers);
  more_powers(*slot, count, second);
  return *slot;
}

namespace {

// The uniform cubic B-spline's refinement weight, in one direction, of the parent control
// point at distance d (in parent spacings) from a child control point.
double bspline_weight(double d) {
  d = std::fabs(d);
  if (d == 0) return 0.75;
  if (d == 1) return 0.125;
  if (d == 0.5) return 0.5;
  return 0;
}

}  // namespace

bool LimitNodes::grid_locked(LimitNode& n) {
  if (triangles_ || n.kept != 16 || n.level.face_size(n.face) != 4) return false;
  const std::vector<Uv> at = unfold(n.level, n.face, false);
  std::array<bool, 16> seen{};
  for (Index l = 0; l < 16; ++l) {
    const Uv x = at[size_t(l)];
    if (!(x[0] >= -1 && x[0] <= 2 && x[1] >= -1 && x[1] <= 2) || x[0] != std::floor(x[0]) || x[1] != std::floor(x[1]))
      return false;
    const int k = int(x[1] + 1) * 4 + int(x[0] + 1);
    if (seen[size_t(k)]) return false;
    seen[size_t(k)] = true;
    n.grid[size_t(k)] = l;
  }
  return true;
}

// One step of node `id` is the B-spline's: each child's grid point is refined from the
// parent's grid with the tensor-product weights, and nothing else.
bool LimitNodes::bspline_step_locked(int id) {
  LimitNode& n = expand_locked(id);
  if (!grid_locked(n)) return false;
  std::array<int, 16> cell_of{};
  cell_of.fill(-1);
  for (int k = 0; k < 16; ++k) cell_of[size_t(n.grid[size_t(k)])] = k;
  for (size_t c = 0; c < n.children.size(); ++c) {
    LimitNode& child = *nodes_[size_t(n.child_node[c])];
    if (!grid_locked(child)) return false;
    const auto& C = n.children[c].corners;
    if (C.size() != 4) return false;
    const StepMatrix& m = n.child_matrix[c];
    for (int k = 0; k < 16; ++k) {
      const double a = k % 4 - 1, b = k / 4 - 1;  // the child grid point, in the child's frame
      const double X = C[0][0] + a * (C[1][0] - C[0][0]) + b * (C[3][0] - C[0][0]);
      const double Y = C[0][1] + a * (C[1][1] - C[0][1]) + b * (C[3][1] - C[0][1]);
      std::array<double, 16> expected{};
      for (int q = 0; q < 16; ++q) expected[size_t(q)] = bspline_weight(X - (q % 4 - 1)) * bspline_weight(Y - (q / 4 - 1));
      const Index row = child.grid[size_t(k)];
      for (Index e = m.offsets[size_t(row)]; e < m.offsets[size_t(row) + 1]; ++e) {
        const int q = cell_of[size_t(m.columns[size_t(e)])];
        if (q < 0) return false;
        expected[size_t(q)] -= m.weights[size_t(e)];
      }
      for (double r : expected)
        if (std::fabs(r) > 1e-13) return false;
    }
  }
  return true;
}

const std::array<Index, 16>* LimitNodes::bspline(int id) {
  return tbb::this_task_arena::isolate([&] { return bspline_isolated(id); });
}

const std::array<Index, 16>* LimitNodes::bspline_isolated(int id) {
  std::lock_guard lock(mutex_);
  LimitNode& n = *nodes_[size_t(id)];
  if (n.bspline == 0) {
    // Every node reachable from this one must take B-spline steps.
    std::vector<int> stack{id}, seen{id};
    bool ok = true;
    while (ok && !stack.empty()) {
      const int x = stack.back();
      stack.pop_back();
      if (nodes_[size_t(x)]->bspline == 1) continue;
      if (nodes_[size_t(x)]->bspline == 2 || !bspline_step_locked(x)) {
        ok = false;
        break;
      }
      for (int c : nodes_[size_t(x)]->child_node)
        if (std::find(seen.begin(), seen.end(), c) == seen.end()) seen.push_back(c), stack.push_back(c);
      if (seen.size() > 64) ok = false;  // not a regular region: leave it to the descent
    }
    if (ok)
      for (int x : seen) nodes_[size_t(x)]->bspline = 1;
    else
      n.bspline = 2;
  }
  return n.bspline == 1 ? &n.grid : nullptr;
}

const PolynomialPatch* LimitNodes::quartic(int id, bool& untried) {
  std::lock_guard lock(mutex_);
  const LimitNode& n = *nodes_[size_t(id)];
  untried = n.quartic == 0;
  return n.quartic == 1 ? &n.patch : nullptr;
}

void LimitNodes::set_quartic(int id, PolynomialPatch patch) {
  std::lock_guard lock(mutex_);
  LimitNode& n = *nodes_[size_t(id)];
  if (n.quartic != 0) return;
  n.quartic = patch.lattice.empty() ? 2 : 1;
  n.patch = std::move(patch);
}

const CornerRows* LimitNodes::corner(int id, int k, NoLimitMask& error) {
  return tbb::this_task_arena::isolate([&] { return corner_isolated(id, k, error); });
}

const CornerRows* LimitNodes::corner_isolated(int id, int k, NoLimitMask& error) {
  std::lock_guard lock(mutex_);
  LimitNode& n = *nodes_[size_t(id)];
  if (!n.corner_tried[size_t(k)]) {
    n.corner_tried[size_t(k)] = 1;
    FacePoint p;
    p.face = n.face;
    CornerRows rows;
    NoLimitMask why;
    if (corner_rows(limits_, n.level, p, k, 0, triangles_, rows, why, analysis_parameter_scale(scheme_))) {
      auto by_label = [&](const std::vector<double>& r) {
        std::vector<double> out(size_t(n.kept), 0.0);
        for (size_t v = 0; v < r.size(); ++v) {
          if (r[v] == 0) continue;
          if (n.label_of[v] >= n.kept) throw NotClosed(not_closed(scheme_, depth_));
          out[size_t(n.label_of[v])] = r[v];
        }
        return out;
      };
      n.corner[size_t(k)].position = by_label(rows.position);
      if (!rows.no_derivatives.empty()) n.corner[size_t(k)].no_derivatives = not_c1_derivatives(scheme_, rows.no_derivatives);
      if (!rows.ds.empty()) n.corner[size_t(k)].ds = by_label(rows.ds), n.corner[size_t(k)].dt = by_label(rows.dt);
      n.corner_ready[size_t(k)] = 1;
    } else {
      n.corner_error[size_t(k)] = why;
    }
  }
  if (!n.corner_ready[size_t(k)] && !n.corner_error[size_t(k)].verdict.empty()) error = n.corner_error[size_t(k)];
  return n.corner_ready[size_t(k)] ? &n.corner[size_t(k)] : nullptr;
}

}  // namespace subdiv
