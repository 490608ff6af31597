#include "framework/limit/sqrt3_nodes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <fmt/format.h>
#include <tbb/task_arena.h>

#include "framework/analysis/surface/local_patch.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/engine/refiner.h"
#include "framework/limit/canonical_cut.h"
#include "framework/limit/cut_weight_tables.h"
#include "framework/limit/two_steps.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Barycentric coordinates in the frame of triangle f of the first step's children: f's corners,
// f's point at its centroid, and the point of each neighbour across an edge of f at the
// neighbour's centroid with the grid unfolded affinely across the edge (its far corner at
// a + b - c), written per face, not per far corner: on a small mesh (a tetrahedron) the three
// neighbours share their far corner.
std::vector<Bary> first_step_coordinates(const Level& L, Index f, const ChildOrigins& o) {
  std::vector<Bary> out(o.kind.size(), Bary{kNan, kNan, kNan});
  const auto fv = L.face(f);
  const auto fe = L.face_edge_list(f);
  for (size_t v = 0; v < o.kind.size(); ++v) {
    if (o.kind[v] == OriginKind::Vertex) {
      for (int k = 0; k < 3; ++k)
        if (fv[size_t(k)] == o.parent[v]) out[v] = Bary{0, 0, 0}, out[v][size_t(k)] = 1;
    } else if (o.kind[v] == OriginKind::Face) {
      const Index g = o.parent[v];
      if (g == f) out[v] = Bary{1.0 / 3, 1.0 / 3, 1.0 / 3};
      for (int k = 0; k < 3 && g != f; ++k) {
        const Index e = fe[size_t(k)];
        if (L.edge_faces[size_t(2 * e)] != g && L.edge_faces[size_t(2 * e + 1)] != g) continue;
        Bary x{0, 0, 0};
        x[size_t(k)] = 2.0 / 3, x[size_t((k + 1) % 3)] = 2.0 / 3, x[size_t((k + 2) % 3)] = -1.0 / 3;
        out[v] = x;
      }
    }
  }
  return out;
}

// Where the children of a step lie: a vertex child at its parent vertex, a face child at the
// centroid of its parent face, a boundary edge's trisection point (Kobbelt 2000, section 5:
// the second step trisects the boundary) a third of the way from the end it is next to (the
// parameterisation, whatever the rules' weights).
std::vector<Bary> child_coordinates(const Level& parent, const std::vector<Bary>& at, const ChildOrigins& o) {
  std::vector<Bary> out(o.kind.size(), Bary{kNan, kNan, kNan});
  for (size_t v = 0; v < o.kind.size(); ++v) {
    if (o.kind[v] == OriginKind::Vertex) {
      out[v] = at[size_t(o.parent[v])];
    } else if (o.kind[v] == OriginKind::Edge) {
      // Local 0 is the point next to the edge's first end (refine/sqrt3_split.cpp).
      const Index e = o.parent[v];
      const Bary& near = at[size_t(parent.edge_vertices[size_t(2 * e + o.local[v])])];
      const Bary& far = at[size_t(parent.edge_vertices[size_t(2 * e + 1 - o.local[v])])];
      for (size_t i = 0; i < 3; ++i) out[v][i] = (2 * near[i] + far[i]) / 3;
    } else if (o.kind[v] == OriginKind::Face) {
      Bary sum{0, 0, 0};
      const auto corners = parent.face(o.parent[v]);
      for (Index w : corners)
        for (size_t i = 0; i < 3; ++i) sum[i] += at[size_t(w)][i];
      for (double& x : sum) x /= double(corners.size());
      out[v] = sum;
    }
  }
  return out;
}

std::optional<Lattice> on_lattice(const Bary& b) {
  Lattice l{};
  for (size_t i = 0; i < 3; ++i) {
    const double x = 3 * b[i];
    if (!std::isfinite(x) || std::fabs(x - std::round(x)) > 1e-9 || std::round(x) < 0) return std::nullopt;
    l[i] = int(std::round(x));
  }
  return l;
}

// The nine triangles of level 2 inside the face, in the order of the level's faces.
std::vector<std::pair<Index, TriadicChild>> triadic_children(const Level& level2, const std::vector<Bary>& at) {
  std::vector<std::pair<Index, TriadicChild>> out;
  for (Index g = 0; g < level2.face_count(); ++g) {
    const auto gv = level2.face(g);
    if (gv.size() != 3) continue;
    std::array<Lattice, 3> c{};
    bool inside = true;
    for (size_t m = 0; m < 3 && inside; ++m) {
      const auto l = on_lattice(at[size_t(gv[m])]);
      if (!l) inside = false;
      else c[m] = *l;
    }
    if (!inside) continue;
    TriadicChild t;
    Lattice lo{}, hi{};
    for (size_t i = 0; i < 3; ++i) {
      lo[i] = std::min({c[0][i], c[1][i], c[2][i]});
      hi[i] = std::max({c[0][i], c[1][i], c[2][i]});
    }
    t.up = lo[0] + lo[1] + lo[2] == 2;
    if (!t.up && hi[0] + hi[1] + hi[2] != 4)
      throw Error("internal: a sqrt3 child triangle is not a cell of the triadic lattice");
    t.anchor = t.up ? lo : hi;
    for (size_t m = 0; m < 3; ++m)
      for (int i = 0; i < 3; ++i)
        if (c[m][size_t(i)] != t.anchor[size_t(i)]) t.q[m] = i;
    out.emplace_back(g, t);
  }
  if (out.size() != 9)
    throw Error(fmt::format("internal: two sqrt3 steps made {} triangles in a face, not the 9 of a triadic split",
                            out.size()));
  return out;
}

// Rings of a corner within which a boundary vertex takes the corner's derivatives away.
constexpr int kBoundaryRings = 4;

// A vertex on a boundary, a sharp or semi-sharp edge, or tagged sharp: Kobbelt's boundary
// rules apply there (refine/sqrt3_split.cpp: sharp edges are kept and trisected like a
// boundary).
bool on_feature(const Level& L, Index v) {
  if (L.on_boundary(v) || L.vertex_sharp(v) > 0) return true;
  for (Index e : L.ring_edges(v))
    if (L.edge_sharp(e) > 0) return true;
  return false;
}

// A vertex where the descent need not go on past the last triangle touching it: 6 faces and
// no sharp edge, or two straight across (a regular crease); 3 faces on a boundary, no sharp
// edge inside. The rest (other valences, darts, corners, tagged vertices) are extraordinary.
bool regular_corner(const Level& L, Index v) {
  if (L.vertex_sharp(v) > 0) return false;
  const auto ring = L.ring_edges(v);
  const int n = int(ring.size());
  std::vector<int> sharp;
  for (int j = 0; j < n; ++j)
    if (L.edge_sharp(ring[size_t(j)]) > 0 && !L.edge_on_boundary(ring[size_t(j)])) sharp.push_back(j);
  if (L.on_boundary(v)) return sharp.empty() && L.incident_face_count(v) == 3;
  return L.incident_face_count(v) == 6 && (sharp.empty() || (sharp.size() == 2 && sharp[1] - sharp[0] == 3));
}

// Whether a vertex within `rings` edges of `from` satisfies `pred` (rings fewer than the cut's
// radius, so the cut's rim is not met).
template <class Pred>
bool any_within(const Level& L, std::vector<Index> from, int rings, Pred pred) {
  std::vector<Index> seen = from;
  for (int r = 0; r <= rings; ++r) {
    std::vector<Index> next;
    for (Index w : from) {
      if (pred(w)) return true;
      for (Index e : L.ring_edges(w)) {
        const Index x = L.other_end(e, w);
        if (std::find(seen.begin(), seen.end(), x) == seen.end()) seen.push_back(x), next.push_back(x);
      }
    }
    from.swap(next);
  }
  return false;
}

// Whether a vertex on a feature lies within `rings` edges of v.
bool near_boundary(const Level& L, Index v, int rings) {
  return any_within(L, {v}, rings, [&](Index w) { return on_feature(L, w); });
}

// Every vertex within `rings` edges of the face's corners is interior, of valence 6 and
// without sharpness.
bool regular_disc(const Level& L, Index face, int rings) {
  const auto corners = L.face(face);
  return !any_within(L, std::vector<Index>(corners.begin(), corners.end()), rings,
                     [&](Index w) { return on_feature(L, w) || L.incident_face_count(w) != 6; });
}

}  // namespace

Bary in_child(const TriadicChild& t, const Bary& b) {
  Bary beta{};
  for (size_t m = 0; m < 3; ++m) {
    const double x = 3 * b[size_t(t.q[m])];
    beta[m] = t.up ? x - t.anchor[size_t(t.q[m])] : t.anchor[size_t(t.q[m])] - x;
  }
  const size_t k = size_t(std::max_element(beta.begin(), beta.end()) - beta.begin());
  beta[k] = 1 - beta[(k + 1) % 3] - beta[(k + 2) % 3];
  return beta;
}

std::array<double, 2> child_gradient(const TriadicChild& t, int m) {
  constexpr double kGrad[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  const double sign = t.up ? 1 : -1;
  return {sign * kGrad[t.q[size_t(m)]][0], sign * kGrad[t.q[size_t(m)]][1]};
}

Sqrt3Nodes::Sqrt3Nodes(const Scheme& scheme, const FeatureOptions& features, int radius, SchemeLimits& limits)
    : scheme_(scheme), features_(features), radius_(radius), limits_(limits), tables_(cut_weight_tables(scheme)) {}

Sqrt3Nodes::~Sqrt3Nodes() = default;

int Sqrt3Nodes::intern(const Level& cut, Index face, std::vector<Index>& order) {
  return tbb::this_task_arena::isolate([&] {
    std::lock_guard lock(mutex_);
    return intern_locked(cut, face, order);
  });
}

int Sqrt3Nodes::intern_locked(const Level& cut, Index face, std::vector<Index>& order) {
  const Labelling lab = label_neighbourhood(cut, CentreKind::Face, face, 0, radius_ + 3);
  if (lab.vertices.size() != size_t(cut.vertex_count))
    throw Error("internal: a cut for sqrt3 limit evaluation has vertices its labelling does not reach");
  order = lab.vertices;
  auto [it, inserted] = index_.emplace(lab.signature, int(nodes_.size()));
  if (!inserted) return it->second;
  auto n = std::make_unique<Sqrt3Node>();
  n->level = canonical_cut(cut, lab, face, n->face);
  // A corner is regular with 6 triangles inside, 3 on a boundary (Kobbelt's boundary rule keeps
  // that count at even levels, refine/sqrt3_split.cpp).
  for (Index v : n->level.face(n->face)) n->extraordinary = n->extraordinary || !regular_corner(n->level, v);
  if (regular_disc(n->level, n->face, radius_ - 1)) {
    std::vector<Uv> at = unfold(n->level, n->face, true);
    if (std::all_of(at.begin(), at.end(), [](const Uv& x) { return std::isfinite(x[0]) && std::isfinite(x[1]); })) {
      n->affine.emplace();
      n->affine->at = std::move(at);
      const auto corners = n->level.face(n->face);
      std::copy(corners.begin(), corners.end(), n->affine->corners.begin());
    }
  }
  nodes_.push_back(std::move(n));
  return it->second;
}

const Sqrt3Node& Sqrt3Nodes::expanded(int id) {
  return *tbb::this_task_arena::isolate([&]() -> const Sqrt3Node* {
    std::lock_guard lock(mutex_);
    return &expand_locked(id);
  });
}

Sqrt3Node& Sqrt3Nodes::expand_locked(int id) {
  Sqrt3Node* n = nodes_[size_t(id)].get();
  if (n->expanded) return *n;
  RefineOptions ro;
  ro.levels = 2;
  ro.features = features_;
  ro.evaluation.weight_tables = tables_.get();
  const Hierarchy h = refine(scheme_, n->level, ro);
  const std::vector<Bary> at1 = first_step_coordinates(n->level, n->face, h.origins[0]);
  const std::vector<Bary> at2 = child_coordinates(h.levels[1], at1, h.origins[1]);
  for (const auto& [g, t] : triadic_children(h.levels[2], at2)) {
    const Extracted e = extract_neighbourhood(h.levels[2], CentreKind::Face, g, radius_);
    Index local = kNone;
    for (size_t f = 0; f < e.face_original.size(); ++f)
      if (e.face_original[f] == g) local = Index(f);
    std::vector<Index> order;
    const int child = intern_locked(e.level, local, order);
    n = nodes_[size_t(id)].get();
    std::vector<Index> rows;
    for (Index v : order) rows.push_back(e.original[size_t(v)]);
    n->children.push_back(t);
    n->child_node.push_back(child);
    n->child_matrix.push_back(two_step_matrix(h, rows, n->level.vertex_count, 3));
    n->powers.emplace_back();
  }
  n->expanded = true;
  return *n;
}

const Sqrt3Node::Powers& Sqrt3Nodes::powers(int id, int which, bool second) {
  std::lock_guard lock(mutex_);
  Sqrt3Node& n = *nodes_[size_t(id)];
  auto& slot = n.powers[size_t(which)];
  // A double sqrt3 step scales by 3: first-derivative rows by 3, second ones by 9.
  if (!slot) slot = lazy_step_powers(n.child_matrix[size_t(which)], 3, kPowers, n.affine ? &*n.affine : nullptr);
  more_powers(*slot, kPowers, second);
  return *slot;
}

const CornerRows* Sqrt3Nodes::corner(int id, int k, NoLimitMask& error) {
  return tbb::this_task_arena::isolate([&]() -> const CornerRows* {
    std::lock_guard lock(mutex_);
    Sqrt3Node& n = *nodes_[size_t(id)];
    if (n.corner_state[size_t(k)] == 0) {
      FacePoint p;
      p.face = n.face;
      n.corner_state[size_t(k)] =
          corner_rows(limits_, n.level, p, k, 0, true, n.corner[size_t(k)], n.corner_error[size_t(k)],
                      analysis_parameter_scale(scheme_), true)
              ? 1
              : 2;
      // No derivatives within a few rings of a boundary: the tangent masks are scaled by
      // linear precision (corner_limit.h), which √3's boundary rules lack there (the first
      // step's face point of a boundary triangle has 5 neighbours, and the vertex rule moves it
      // off its parameter; measured: exact two rings inside, 3x off on the boundary itself).
      // Points that far from the boundary, 3^-34 of the base triangle, lie on it to round-off.
      const Index c = n.level.face(n.face)[size_t(k)];
      if (near_boundary(n.level, c, std::min(kBoundaryRings, radius_ - 1))) {
        // Off the boundary, the rings to it grow threefold per double step: derivatives a few
        // steps on (sqrt3_limit.cpp).
        n.corner_deferred[size_t(k)] = !n.corner[size_t(k)].ds.empty() && !on_feature(n.level, c);
        // Nor is there a scale to compare with there: a regular boundary vertex's eigenvalues
        // (the interpolating √3's 1/3, 0.264) say nothing about derivatives it does not give.
        n.corner[size_t(k)].no_derivatives.clear();
        for (auto* row : {&n.corner[size_t(k)].ds, &n.corner[size_t(k)].dt, &n.corner[size_t(k)].dss,
                          &n.corner[size_t(k)].dst, &n.corner[size_t(k)].dtt})
          row->clear();
      }
    }
    if (n.corner_state[size_t(k)] == 2) {
      if (!n.corner_error[size_t(k)].verdict.empty()) error = n.corner_error[size_t(k)];
      return nullptr;
    }
    return &n.corner[size_t(k)];
  });
}

}  // namespace subdiv
