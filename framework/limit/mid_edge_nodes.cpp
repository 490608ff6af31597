#include "framework/limit/mid_edge_nodes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <tbb/task_arena.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/local_patch.h"
#include "framework/limit/canonical_cut.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/cut_weight_tables.h"
#include "framework/limit/four_direction_patch.h"
#include "framework/limit/mid_edge_limit.h"
#include "framework/limit/two_steps.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// d/ds and d/dt at the centre of quad `face` as rows over the level's vertices, from the
// face mask's tangent directions and linear precision (corner_limit.h): the pair of
// directions whose 2 x 2 system is best conditioned. False where the grid around the face is
// not regular within the masks' reach (unfold gives NaN there).
bool centre_derivatives(const LimitMask& mask, const Labelling& lab, const Level& L, Index face, std::vector<double>& ds,
                        std::vector<double>& dt) {
  if (L.face_size(face) != 4 || mask.directions.size() < 2) return false;
  const std::vector<Uv> at = unfold(L, face, false);
  std::vector<std::array<double, 2>> st;
  for (const auto& d : mask.directions) {
    std::array<double, 2> x{0, 0};
    for (size_t l = 0; l < d.size(); ++l)
      if (d[l] != 0)
        for (size_t c = 0; c < 2; ++c) x[c] += d[l] * at[size_t(lab.vertices[l])][c];
    st.push_back(x);
  }
  double best = 0;
  size_t ia = 0, ib = 0;
  for (size_t i = 0; i < st.size(); ++i)
    for (size_t j = i + 1; j < st.size(); ++j) {
      const double det = st[i][0] * st[j][1] - st[i][1] * st[j][0];
      const double size = std::hypot(st[i][0], st[i][1]) * std::hypot(st[j][0], st[j][1]);
      if (std::isfinite(det) && size > 0 && std::fabs(det) / size > best) best = std::fabs(det) / size, ia = i, ib = j;
    }
  if (best < 1e-6) return false;
  const double a00 = st[ia][0], a01 = st[ia][1], a10 = st[ib][0], a11 = st[ib][1];
  const double det = a00 * a11 - a01 * a10;
  const auto& da = mask.directions[ia];
  const auto& db = mask.directions[ib];
  ds.assign(size_t(L.vertex_count), 0.0);
  dt.assign(size_t(L.vertex_count), 0.0);
  for (size_t l = 0; l < std::max(da.size(), db.size()); ++l) {
    const double x = l < da.size() ? da[l] : 0.0, y = l < db.size() ? db[l] : 0.0;
    const size_t v = size_t(lab.vertices[l]);
    ds[v] += (a11 * x - a01 * y) / det;
    dt[v] += (a00 * y - a10 * x) / det;
  }
  return true;
}

// The 3 x 3 points around the quadrant's corner when the double steps refine them as the
// four-direction box spline does, given that the scheme refines a regular closed grid so
// (refines_as_four_direction): the nine points interior, of valence 4, and every face at them
// a quad. Then every rule behind a new point of the quadrant's support — the points of the four
// faces at the corner, made from those faces' edges, with their ends' rings and the faces on
// both sides — reads the regular grid that check saw, and so do the next steps' (their grids lie
// in the F-, E- and V-faces of these faces and points).
std::optional<std::array<Index, 9>> four_direction_grid(const Level& L, Index face, int corner) {
  const auto grid = biquadratic_grid(L, face, corner);
  if (!grid) return std::nullopt;
  for (Index v : *grid) {
    if (L.on_boundary(v) || L.valence(v) != 4 || L.incident_face_count(v) != 4) return std::nullopt;
    for (Index f : L.ring_faces(v))
      if (L.face_size(f) != 4) return std::nullopt;
  }
  return grid;
}

}  // namespace

MidEdgeNodes::MidEdgeNodes(const Scheme& scheme, const FeatureOptions& features, int radius, SchemeLimits& limits)
    : scheme_(scheme), features_(features), radius_(radius), limits_(limits), tables_(cut_weight_tables(scheme)) {}

MidEdgeNodes::~MidEdgeNodes() = default;

int MidEdgeNodes::intern(const Level& cut, Index face, std::vector<Index>& order) {
  return tbb::this_task_arena::isolate([&] {
    std::lock_guard lock(mutex_);
    return intern_locked(cut, face, order);
  });
}

int MidEdgeNodes::intern_locked(const Level& cut, Index face, std::vector<Index>& order) {
  const Labelling lab = label_neighbourhood(cut, CentreKind::Face, face, 0, radius_ + 3);
  if (lab.vertices.size() != size_t(cut.vertex_count))
    throw Error("internal: a cut for mid-edge limit evaluation has vertices its labelling does not reach");
  order = lab.vertices;
  auto [it, inserted] = index_.emplace(lab.signature, int(nodes_.size()));
  if (!inserted) return it->second;
  auto n = std::make_unique<MidEdgeNode>();
  n->level = canonical_cut(cut, lab, face, n->face);
  nodes_.push_back(std::move(n));
  return it->second;
}

const MidEdgeNode& MidEdgeNodes::expanded(int id) {
  return *tbb::this_task_arena::isolate([&]() -> const MidEdgeNode* {
    std::lock_guard lock(mutex_);
    MidEdgeNode& n = *nodes_[size_t(id)];
    if (!n.expanded) {
      RefineOptions ro;
      ro.levels = 2;
      ro.features = features_;
      ro.evaluation.weight_tables = tables_.get();
      n.steps = refine(scheme_, n.level, ro);
      n.origins = mid_edge_double_origins(n.level, n.steps.levels[1], n.steps.origins[0], n.steps.levels[2],
                                          n.steps.origins[1]);
      n.expanded = true;
    }
    return &n;
  });
}

const MidEdgeNode::Child& MidEdgeNodes::child(int id, Index g) {
  return *tbb::this_task_arena::isolate([&]() -> const MidEdgeNode::Child* {
    std::lock_guard lock(mutex_);
    MidEdgeNode* n = nodes_[size_t(id)].get();
    if (const auto it = n->children.find(g); it != n->children.end()) return &it->second;
    const Level& level2 = n->steps.levels[2];
    const Extracted e = extract_neighbourhood(level2, CentreKind::Face, g, radius_);
    Index local = kNone;
    for (size_t f = 0; f < e.face_original.size(); ++f)
      if (e.face_original[f] == g) local = Index(f);
    std::vector<Index> order;
    MidEdgeNode::Child c;
    c.node = intern_locked(e.level, local, order);
    n = nodes_[size_t(id)].get();
    std::vector<Index> rows;
    for (Index v : order) rows.push_back(e.original[size_t(v)]);
    c.matrix = two_step_matrix(n->steps, rows, n->level.vertex_count, 2);
    return &n->children.emplace(g, std::move(c)).first->second;
  });
}

const MidEdgeNode* MidEdgeNodes::centre(int id, std::string& error) {
  return tbb::this_task_arena::isolate([&]() -> const MidEdgeNode* {
    std::lock_guard lock(mutex_);
    MidEdgeNode& n = *nodes_[size_t(id)];
    if (n.centre_state == 0) {
      LocalConfig config;
      config.centre = CentreKind::Face;
      config.valence = n.level.face_size(n.face);
      const auto mask = limits_.mask(config);
      if (!mask->ok) {
        error = mask->error;
        return nullptr;
      }
      Labelling lab;
      n.centre_state = 2;
      if (matches_neighbourhood(lab, n.level, CentreKind::Face, n.face, 0, mask->radius, mask->signature)) {
        n.position.assign(size_t(n.level.vertex_count), 0.0);
        for (size_t l = 0; l < mask->position.size(); ++l) n.position[size_t(lab.vertices[l])] += mask->position[l];
        if (!centre_derivatives(*mask, lab, n.level, n.face, n.ds, n.dt)) n.ds.clear(), n.dt.clear();
        n.centre_state = 1;
      }
    }
    return n.centre_state == 1 ? &n : nullptr;
  });
}

const std::array<Index, 9>* MidEdgeNodes::quadrant_grid(int id, int corner) {
  return tbb::this_task_arena::isolate([&]() -> const std::array<Index, 9>* {
    std::lock_guard lock(mutex_);
    MidEdgeNode& n = *nodes_[size_t(id)];
    int& state = n.grid_state[size_t(corner)];
    if (state == 0) {
      const auto grid = four_direction_grid(n.level, n.face, corner);
      state = grid ? 1 : 2;
      if (grid) n.grid[size_t(corner)] = *grid;
    }
    return state == 1 ? &n.grid[size_t(corner)] : nullptr;
  });
}

}  // namespace subdiv
