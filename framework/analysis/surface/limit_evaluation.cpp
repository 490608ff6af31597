#include "framework/analysis/surface/limit_evaluation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "framework/analysis/surface/rim_rules.h"
#include "framework/analysis/curve/curve_scheme_analysis.h"
#include "framework/analysis/surface/sparse_rows.h"
#include "framework/analysis/surface/surface_analysis.h"
#include "framework/refine/child_tags.h"
#include "framework/rules/formula.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/parallel_for_all.h"

namespace subdiv {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalised(const Vec3& a) {
  const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  if (!(l > 0) || !std::isfinite(l)) return {0, 0, 0};
  return {a[0] / l, a[1] / l, a[2] / l};
}
Vec3 point(std::span<const double> p, Index v) { return {p[size_t(3 * v)], p[size_t(3 * v + 1)], p[size_t(3 * v + 2)]}; }

// A vertex's (or a dual face's) limit as rows over the level's vertices.
struct LimitRows {
  SparseRow position;
  std::vector<SparseRow> directions;  // towards the ring neighbours; < 2: no tangent plane
  bool cyclic = true;
  bool exact = false;         // the position is exact
  bool normal_exact = true;   // false: the normal is to be estimated
  std::string reason;         // when not exact
};

LimitRows pulled_back(LimitRows r, const StencilTable& step) {
  r.position = pull_back(r.position, step);
  for (auto& d : r.directions) d = pull_back(d, step);
  return r;
}

LimitRows renumbered(LimitRows r, const std::vector<Index>& original) {
  r.position = renumber(r.position, original);
  for (auto& d : r.directions) d = renumber(d, original);
  return r;
}

Index child_vertex(const ChildOrigins& o, Index v) {
  for (size_t c = 0; c < o.kind.size(); ++c)
    if (o.kind[c] == OriginKind::Vertex && o.parent[c] == v) return Index(c);
  return kNone;
}

// Does child vertex c come from an element incident to parent vertex v?
bool descends_from(const Level& parent, const ChildOrigins& o, Index c, Index v) {
  const Index p = o.parent[size_t(c)];
  switch (o.kind[size_t(c)]) {
    case OriginKind::Vertex: return p == v;
    case OriginKind::Edge: return parent.edge_vertices[size_t(2 * p)] == v || parent.edge_vertices[size_t(2 * p + 1)] == v;
    case OriginKind::Corner: return parent.face(p)[o.local[size_t(c)]] == v;
    case OriginKind::Face: return false;
  }
  return false;
}

// The face a vertex becomes in a dual split (its V-face): every corner descends from v.
Index vertex_face(const Level& parent, const Level& child, const ChildOrigins& o, Index v) {
  for (Index g = 0; g < child.face_count(); ++g) {
    if (o.parent_face[size_t(g)] != kNone) continue;
    bool all = true;
    for (Index c : child.face(g))
      if (!descends_from(parent, o, c, v)) { all = false; break; }
    if (all) return g;
  }
  return kNone;
}

// The face a face becomes in a dual split (its F-face).
Index face_face(const Level& parent, const Level& child, const ChildOrigins& o, Index f) {
  for (Index g = 0; g < child.face_count(); ++g)
    if (o.parent_face[size_t(g)] == f && child.face_size(g) == parent.face_size(f)) return g;
  return kNone;
}

// The control point itself, or the face's centroid: what an approximation falls back on.
LimitRows approximate(const Level& L, CentreKind kind, Index c, std::string reason) {
  LimitRows out;
  out.exact = false;
  out.normal_exact = false;
  out.reason = std::move(reason);
  if (kind == CentreKind::Vertex) {
    out.position = {{c, 1.0}};
  } else {
    const auto vs = L.face(c);
    for (Index v : vs) out.position.emplace_back(v, 1.0 / double(vs.size()));
    normalise_row(out.position);
  }
  return out;
}

// Why a vertex or face has no limit mask at any level, or null. A non-manifold vertex (on
// an edge of three or more faces, a duplicated face, or joining two fans) stays non-manifold
// in every refinement, so refining its neighbourhood to find an analysable one could never
// succeed: it searched 12 levels (5-73 s on meshes of 5-8 vertices).
const char* no_limit_reason(const Level& L, CentreKind kind, Index c) {
  if (L.manifold()) return nullptr;
  const char* reason = "non-manifold neighbourhood (an edge of three or more faces, a duplicated face, or fans "
                       "joined at a vertex): no limit mask exists; the control point is used";
  if (kind == CentreKind::Vertex) return L.non_manifold_vertex(c) ? reason : nullptr;
  for (Index v : L.face(c))
    if (L.non_manifold_vertex(v)) return reason;
  return nullptr;
}

LimitRows mask_rows(const LimitMask& m, const Labelling& lab) {
  auto row = [&](const std::vector<double>& mask) {
    SparseRow r;
    for (size_t t = 0; t < mask.size(); ++t)
      if (mask[t] != 0.0) r.emplace_back(lab.vertices[t], mask[t]);
    normalise_row(r);
    return r;
  };
  LimitRows out;
  out.position = row(m.position);
  for (const auto& d : m.directions) out.directions.push_back(row(d));
  out.cyclic = m.cyclic;
  out.exact = true;
  return out;
}

Vec3 applied(const SparseRow& row, std::span<const double> P) {
  Vec3 q{0, 0, 0};
  apply_row(row, P, 3, q);
  return q;
}

double applied_scalar(const SparseRow& row, std::span<const double> w) {
  double q = 0;
  apply_row(row, w, 1, std::span<double>(&q, 1));
  return q;
}

// A direction of the surface: of P itself, or with weights of the projected rational
// surface X/W at the limit point p, by the quotient rule (D X - p D W) / W.
Vec3 direction(const SparseRow& row, std::span<const double> P, std::span<const double> w, const Vec3& p, double W) {
  Vec3 d = applied(row, P);
  if (w.empty()) return d;
  const double dw = applied_scalar(row, w);
  for (size_t i = 0; i < 3; ++i) d[i] = (d[i] - p[i] * dw) / W;
  return d;
}

// The normal from the direction rows: the sum of the sector normals.
Vec3 normal_of(const LimitRows& r, std::span<const double> P, std::span<const double> w = {}, const Vec3& p = {},
               double W = 1) {
  const size_t k = r.directions.size();
  std::vector<Vec3> d(k);
  for (size_t j = 0; j < k; ++j) d[j] = direction(r.directions[j], P, w, p, W);
  Vec3 n{0, 0, 0};
  for (size_t j = 0; j + (r.cyclic ? 0 : 1) < k; ++j) {
    const Vec3 c = cross(d[j], d[(j + 1) % k]);
    n[0] += c[0], n[1] += c[1], n[2] += c[2];
  }
  return normalised(n);
}

}  // namespace

bool scheme_is_level_dependent(const Scheme& scheme) {
  FormulaSet formulas(scheme.parameter_values(), scheme.definitions);
  const auto reads_level = [&](const std::optional<Rule>& rule) {
    if (!rule) return false;
    for (const auto& term : rule->terms) {
      if (!term.weight.empty() && formulas.uses(formulas.add(term.weight, term.where)).l) return true;
      for (const auto& w : term.curve_weights)
        if (formulas.uses(formulas.add(w, term.where)).l) return true;
    }
    return false;
  };
  for (const auto& step : scheme.steps) {
    for (const auto& by_context : step.rules)
      for (const auto& rule : by_context)
        if (reads_level(rule)) return true;
    bool crease_end_reads_level = false;
    step.crease_ends.each([&](int, int, const std::optional<Rule>& rule) {
      crease_end_reads_level = crease_end_reads_level || reads_level(rule);
    });
    if (crease_end_reads_level || (step.curve && curve_scheme_is_level_dependent(*step.curve))) return true;
  }
  return scheme.curve && curve_scheme_is_level_dependent(*scheme.curve);
}

struct SchemeLimits::Impl {
  const Scheme& scheme;
  LimitOptions options;
  CentreKind centre;
  PatchCells cells;
  bool level_dependent = false;
  bool alternating = false;
  std::mutex mutex;
  std::map<LocalConfig, std::shared_ptr<const LimitMask>> cache;
  std::vector<std::string> reasons;

  Impl(const Scheme& s, const LimitOptions& o) : scheme(s), options(o) {
    centre = analysis_centre(s);
    cells = analysis_cells(s);
    level_dependent = scheme_is_level_dependent(s);
    alternating = splitter_info(s.split()).feature_period > 1;
  }

  SurfaceAnalysisOptions analysis_options() const {
    SurfaceAnalysisOptions so;
    so.features = options.features;
    so.characteristic_map = false;
    return so;
  }

  LocalConfig key(LocalConfig c) const {
    c.first_step = level_dependent ? c.first_step : alternating ? c.first_step % 2 : 0;
    return c;
  }

  // The ring the masks reach (they are trimmed to whole rings).
  static int support_ring(const SurfaceAnalysis& a, const LimitMask& m) {
    size_t size = m.position.size();
    for (const auto& d : m.directions) size = std::max(size, d.size());
    return size ? a.distance[size - 1] : 0;
  }

  static void take_masks(const SurfaceAnalysis& a, LimitMask& m) {
    if (!a.error.empty() || !a.has_limit_mask) {
      m.error = a.verdict;
      if (a.outcome == Verdict::Fails) m.failure = a.failure;
      return;
    }
    m.position = a.limit_mask;
    m.directions = a.direction_masks;
    m.direction_eigenvalues = a.direction_eigenvalues;
    m.cyclic = a.directions_cyclic;
    m.ok = true;
  }

  // The masks the analysis finds at the centre of patch p (a vertex or a face), labelled
  // around that centre.
  LimitMask analysed_mask(const Patch& p, const LocalConfig& c) const {
    LimitMask m;
    m.centre = c.centre;
    const SurfaceAnalysis a = analyse_patch(scheme, p, c, analysis_options());
    take_masks(a, m);
    if (!m.ok) return m;
    m.radius = support_ring(a, m) + 1;
    m.signature = label_neighbourhood(p.level, p.centre_kind, p.centre, p.start, m.radius).signature;
    if (!a.quadratic_masks.empty()) {
      m.quadratic = a.quadratic_masks;
      m.quadratic_radius = a.distance[a.quadratic_masks[0].size() - 1] + 1;
      m.quadratic_signature = label_neighbourhood(p.level, p.centre_kind, p.centre, p.start, m.quadratic_radius).signature;
    }
    return m;
  }

  // Masks over a step's child vertices pulled back through the step's stencils `t` onto the
  // parent vertices: per parent vertex, its weight in the position mask, then in each
  // direction mask.
  static std::map<Index, std::vector<double>> pull_back_masks(const LimitMask& child, const std::vector<Index>& child_vertex,
                                                        const StencilTable& t) {
    const size_t k = child.directions.size();
    std::map<Index, std::vector<double>> pulled;
    auto pull = [&](size_t slot, const std::vector<double>& mask) {
      for (size_t i = 0; i < mask.size(); ++i) {
        if (mask[i] == 0.0) continue;
        const Index cv = child_vertex[i];
        for (Index e = t.offsets[size_t(cv)]; e < t.offsets[size_t(cv) + 1]; ++e) {
          auto& w = pulled[t.indices[size_t(e)]];
          w.resize(k + 1, 0.0);
          w[slot] += mask[i] * t.weights[size_t(e)];
        }
      }
    };
    pull(0, child.position);
    for (size_t j = 0; j < k; ++j) pull(j + 1, child.directions[j]);
    return pulled;
  }

  // Pulled weights laid out by the labels around vertex p.centre, trimmed to whole rings.
  static void store_pulled(const Patch& p, const std::map<Index, std::vector<double>>& pulled, size_t directions,
                           int reach, LimitMask& m) {
    Labelling lab = label_neighbourhood(p.level, CentreKind::Vertex, p.centre, p.start, reach);
    size_t size = 0;
    for (const auto& [v, w] : pulled) {
      bool nonzero = false;
      for (double x : w) nonzero |= x != 0.0;
      if (!nonzero) continue;
      const Index l = lab.label_of[size_t(v)];
      if (l == kNone) throw Error("a V-face mask reaches beyond the labelled neighbourhood");
      size = std::max(size, size_t(l) + 1);
    }
    m.radius = (size ? lab.distance[size - 1] : 0) + 1;
    lab = label_neighbourhood(p.level, CentreKind::Vertex, p.centre, p.start, m.radius);
    m.position.assign(size, 0.0);
    m.directions.assign(directions, std::vector<double>(size, 0.0));
    m.cyclic = true;
    for (const auto& [v, w] : pulled) {
      const Index l = lab.label_of[size_t(v)];
      if (l == kNone || size_t(l) >= size) continue;
      m.position[size_t(l)] = w[0];
      for (size_t j = 0; j < directions; ++j) m.directions[j][size_t(l)] = w[j + 1];
    }
    m.signature = lab.signature;
    m.ok = true;
  }

  // Dual schemes: one step turns the vertex into its V-face; analyse that face in the
  // refined patch and pull its masks back through the step's stencils.
  LimitMask dual_vertex_mask(const Patch& p, const LocalConfig& c) const {
    LimitMask m;
    m.centre = c.centre;
    RefineOptions ro;
    ro.levels = 1, ro.first_step = c.first_step, ro.features = options.features;
    const Hierarchy h = refine(scheme, p.level, ro);
    const Index g = vertex_face(p.level, h.levels[1], h.origins[0], p.centre);
    if (g == kNone) throw Error(fmt::format("the {} becomes no face in a dual step", c.describe()));
    Patch child;
    child.level = h.levels[1];
    child.xy = h.stencils[0].apply(p.xy, 2);
    child.centre_kind = CentreKind::Face;
    child.centre = g;
    child.start = 0;
    LocalConfig fc;
    fc.centre = CentreKind::Face;
    fc.valence = child.level.face_size(g);
    fc.first_step = c.first_step + 1;
    const SurfaceAnalysis a = analyse_patch(scheme, child, fc, analysis_options());
    LimitMask face;
    take_masks(a, face);
    if (!face.ok) {
      m.error = face.error;
      return m;
    }
    store_pulled(p, pull_back_masks(face, a.label_vertices, h.stencils[0]), face.directions.size(), a.ring + 3, m);
    m.direction_eigenvalues = face.direction_eigenvalues;
    return m;
  }

  // The masks of configuration c: analysed at a face or vertex centre, or (dual schemes)
  // pulled back from the vertex's V-face.
  LimitMask compute(const LocalConfig& c) const {
    const int rings = analysis_options().max_ring + 3;
    try {
      if (c.centre == CentreKind::Face) {
        if (c.boundary || !c.sharp.empty() || c.corner) throw Error("faces are analysed in the interior only");
        return analysed_mask(make_face_patch(c.valence, rings), c);
      }
      const Patch p = make_vertex_patch(centre == CentreKind::Face ? PatchCells::Quads : cells, c, rings);
      return centre == CentreKind::Vertex ? analysed_mask(p, c) : dual_vertex_mask(p, c);
    } catch (const Error& e) {
      LimitMask m;
      m.centre = c.centre;
      m.ok = false;
      m.error = e.what();
      return m;
    }
  }

  std::shared_ptr<const LimitMask> get(const LocalConfig& config) {
    const LocalConfig k = key(config);
    {
      std::lock_guard lock(mutex);
      auto it = cache.find(k);
      if (it != cache.end()) return it->second;
    }
    // Computed without the lock (the engine runs parallel loops inside, and a thread waiting
    // in one may pick up another vertex that needs the cache) and in an isolated arena.
    std::shared_ptr<const LimitMask> m;
    tbb::this_task_arena::isolate([&] { m = std::make_shared<const LimitMask>(compute(config)); });
    std::lock_guard lock(mutex);
    return cache.emplace(k, m).first->second;
  }

  void note(const std::string& reason) {
    std::lock_guard lock(mutex);
    if (std::find(reasons.begin(), reasons.end(), reason) == reasons.end()) reasons.push_back(reason);
  }

  // The mask of the centre, if its neighbourhood is the configuration's.
  bool try_mask(const Level& L, CentreKind kind, Index c, int step, Labelling& lab, LimitRows& out,
                std::shared_ptr<const LimitMask>* found = nullptr) {
    LocalConfig cfg;
    int start = 0;
    bool semi = false;
    if (kind == CentreKind::Vertex) {
      if (L.valence(c) == 0) return false;
      cfg = vertex_config(L, c, step, &semi);
      start = conventional_start(L, c);
    } else {
      cfg.centre = CentreKind::Face;
      cfg.valence = L.face_size(c);
      cfg.first_step = step;
    }
    if (semi) return false;
    auto m = get(cfg);
    if (found) *found = m;
    return apply_if_matching(*m, L, kind, c, start, lab, out);
  }

  static bool apply_if_matching(const LimitMask& m, const Level& L, CentreKind kind, Index c, int start,
                                Labelling& lab, LimitRows& out) {
    if (!m.ok) return false;
    if (!matches_neighbourhood(lab, L, kind, c, start, m.radius, m.signature)) return false;
    out = mask_rows(m, lab);
    if (m.directions.size() < 2) {
      out.normal_exact = false;
      out.reason = "no tangent plane from the eigenvectors (the subdominant eigenvalues are not real, semi-simple "
                   "and dominant): the normal is estimated from the limit points around the vertex";
    }
    return true;
  }

  // A boundary vertex of a dual scheme has no V-face. Its children on the refined boundary
  // straddle it; for Chaikin boundaries the middle of the two is on the limit curve.
  static LimitRows boundary_dual(const Level& L, const Hierarchy& h, Index v) {
    const Level& C = h.levels[1];
    std::vector<Index> kids;
    for (Index c = 0; c < C.vertex_count; ++c)
      if (C.on_boundary(c) && descends_from(L, h.origins[0], c, v)) kids.push_back(c);
    LimitRows out = approximate(L, CentreKind::Vertex, v,
                                "dual scheme, boundary vertex without a V-face: the midpoint of its refined "
                                "boundary points, normal from its faces");
    if (kids.empty()) return out;
    SparseRow middle;
    for (Index c : kids) middle.emplace_back(c, 1.0 / double(kids.size()));
    out.position = pull_back(middle, h.stencils[0]);
    return out;
  }

  RefineOptions one_step(int step) const {
    RefineOptions ro;
    ro.levels = 1, ro.first_step = step, ro.features = options.features;
    return ro;
  }

  // Limit rows of the vertices `which` of a level. Vertices whose neighbourhood is not a
  // known configuration are refined first: the whole level at once when they are many
  // (vertex schemes: the limit of a vertex is the limit of its child), else each
  // neighbourhood cut out on its own.
  std::vector<LimitRows> rows(const Level& level, int step, int depth, const std::vector<Index>& which,
                              std::vector<std::uint8_t>* refined) {
    const size_t count = which.size();
    std::vector<LimitRows> out(count);
    std::vector<const LimitMask*> masks(count, nullptr);
    std::vector<std::shared_ptr<const LimitMask>> keep;
    {
      std::map<LocalConfig, const LimitMask*> seen;
      for (size_t i = 0; i < count; ++i) {
        const Index v = which[i];
        if (level.valence(v) == 0) continue;
        bool semi = false;
        const LocalConfig c = key(vertex_config(level, v, step, &semi));
        if (semi) continue;
        auto it = seen.find(c);
        if (it == seen.end()) {
          keep.push_back(get(c));
          it = seen.emplace(c, keep.back().get()).first;
        }
        masks[i] = it->second;
      }
    }
    std::vector<std::uint8_t> matched(count, 0);
    tbb::enumerable_thread_specific<Labelling> labels;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 256), [&](const tbb::blocked_range<size_t>& range) {
      Labelling& lab = labels.local();
      for (size_t i = range.begin(); i != range.end(); ++i) {
        const LimitMask* m = masks[i];
        const Index v = which[i];
        if (m && apply_if_matching(*m, level, CentreKind::Vertex, v, conventional_start(level, v), lab, out[i]))
          matched[i] = 1;
      }
    });
    std::vector<size_t> rest;
    for (size_t i = 0; i < count; ++i) {
      if (matched[i]) continue;
      // Refining never helps here (see no_limit_reason); answered now, not searched for.
      if (const char* why = no_limit_reason(level, CentreKind::Vertex, which[i]))
        out[i] = approximate(level, CentreKind::Vertex, which[i], why);
      else
        rest.push_back(i);
    }
    if (rest.empty()) return out;
    if (refined)
      for (size_t i : rest) (*refined)[size_t(which[i])] = 1;
    const bool many = rest.size() * 300 >= size_t(level.vertex_count);
    if (centre == CentreKind::Vertex && many && depth < options.max_steps) {
      const Hierarchy h = refine(scheme, level, one_step(step));
      std::vector<Index> child_of(size_t(level.vertex_count), kNone);
      const ChildOrigins& o = h.origins[0];
      for (size_t c = 0; c < o.kind.size(); ++c)
        if (o.kind[c] == OriginKind::Vertex) child_of[size_t(o.parent[c])] = Index(c);
      std::vector<Index> next;
      std::vector<size_t> where;
      for (size_t i : rest) {
        const Index c = child_of[size_t(which[i])];
        if (c == kNone) {
          out[i] = approximate(level, CentreKind::Vertex, which[i], "the vertex has no child vertex");
          continue;
        }
        next.push_back(c), where.push_back(i);
      }
      const std::vector<LimitRows> deeper = rows(h.levels[1], step + 1, depth + 1, next, nullptr);
      tbb::parallel_for(size_t(0), where.size(),
                        [&](size_t k) { out[where[k]] = pulled_back(deeper[k], h.stencils[0]); });
      return out;
    }
    parallel_for_all(rest.size(), [&](size_t k) {
      const size_t i = rest[k];
      Labelling local;
      out[i] = limit_at(level, CentreKind::Vertex, which[i], step, depth, local);
    });
    return out;
  }

  LimitRows limit_at(const Level& L, CentreKind kind, Index c, int step, int depth, Labelling& lab) {
    LimitRows out;
    std::shared_ptr<const LimitMask> m;
    if (try_mask(L, kind, c, step, lab, out, &m)) return out;
    if (kind == CentreKind::Vertex && L.valence(c) == 0) return approximate(L, kind, c, "isolated vertex: no faces");
    if (const char* why = no_limit_reason(L, kind, c)) return approximate(L, kind, c, why);
    if (kind == CentreKind::Face) {
      // A face on the boundary stays on it in every dual step: its limit lies on the
      // boundary curve, at the middle of its boundary edge for Chaikin curves.
      std::vector<Index> boundary_edges;
      for (Index e : L.face_edge_list(c))
        if (L.edge_on_boundary(e)) boundary_edges.push_back(e);
      if (!boundary_edges.empty()) {
        LimitRows b = approximate(L, kind, c,
                                  "dual scheme, face on the boundary: the middle of its boundary edge (the limit "
                                  "for a Chaikin boundary curve), normal of the face");
        b.position.clear();
        for (Index e : boundary_edges)
          for (int end = 0; end < 2; ++end)
            b.position.emplace_back(L.edge_vertices[size_t(2 * e + end)], 1.0 / double(2 * boundary_edges.size()));
        normalise_row(b.position);
        return b;
      }
    }
    // A vertex scheme keeps the configuration from level to level: if its analysis failed,
    // refining will not help.
    if (centre == CentreKind::Vertex && kind == CentreKind::Vertex && m && !m->ok)
      return approximate(L, kind, c, "no limit mask: " + m->error);
    if (depth >= options.max_steps)
      return approximate(L, kind, c,
                         fmt::format("no analysable neighbourhood after {} refinements{}", depth,
                                     m && !m->ok ? " (" + m->error + ")" : ""));
    const int radius = (m && m->ok ? m->radius : 4) + 3;
    const Extracted e = extract_neighbourhood(L, kind, c, radius);
    RefineOptions ro = one_step(step);
    const Hierarchy h = refine(scheme, e.level, ro);
    auto back = [&](const LimitRows& deeper) { return renumbered(pulled_back(deeper, h.stencils[0]), e.original); };
    Labelling child_lab;
    if (kind == CentreKind::Vertex) {
      const Index local = e.local(c);
      if (centre == CentreKind::Vertex) {
        const Index cc = child_vertex(h.origins[0], local);
        if (cc == kNone) return approximate(L, kind, c, "the vertex has no child vertex");
        return back(limit_at(h.levels[1], CentreKind::Vertex, cc, step + 1, depth + 1, child_lab));
      }
      const Index g = vertex_face(e.level, h.levels[1], h.origins[0], local);
      if (g == kNone) return renumbered(boundary_dual(e.level, h, local), e.original);
      return back(limit_at(h.levels[1], CentreKind::Face, g, step + 1, depth + 1, child_lab));
    }
    Index fe = kNone;
    for (size_t f = 0; f < e.face_original.size(); ++f)
      if (e.face_original[f] == c) fe = Index(f);
    const Index g = fe == kNone ? kNone : face_face(e.level, h.levels[1], h.origins[0], fe);
    if (g == kNone) return approximate(L, kind, c, "the face has no child face");
    return back(limit_at(h.levels[1], CentreKind::Face, g, step + 1, depth + 1, child_lab));
  }

  // Rows of every vertex of the level, with the approximations noted.
  std::vector<LimitRows> all_rows(const Level& level, int step, std::vector<std::uint8_t>* refined) {
    std::vector<Index> all(static_cast<size_t>(level.vertex_count));
    for (Index v = 0; v < level.vertex_count; ++v) all[size_t(v)] = v;
    std::vector<LimitRows> r = rows(level, step, 0, all, refined);
    for (const LimitRows& l : r)
      if (!l.exact || !l.normal_exact) note(l.reason);
    return r;
  }
};

SchemeLimits::SchemeLimits(const Scheme& scheme, const LimitOptions& options)
    : impl_(std::make_unique<Impl>(scheme, options)) {}
SchemeLimits::~SchemeLimits() = default;

std::shared_ptr<const LimitMask> SchemeLimits::mask(const LocalConfig& config) { return impl_->get(config); }

std::string SchemeLimits::regular_not_c1() {
  LocalConfig c;
  c.centre = impl_->centre;
  const bool quads = impl_->cells == PatchCells::Quads;
  c.valence = c.centre == CentreKind::Face ? (quads ? 4 : 3) : (quads ? 4 : 6);
  c.first_step = impl_->options.first_step;
  const std::shared_ptr<const LimitMask> m = mask(c);
  if (!m->ok) return {};
  return eigenvalues_off_scale(m->direction_eigenvalues, analysis_parameter_scale(impl_->scheme));
}

std::string eigenvalues_off_scale(const std::vector<double>& eigenvalues, double scale) {
  if (scale <= 0) return {};
  for (double z : eigenvalues)
    if (std::fabs(z - scale) > 1e-6 * scale) {
      std::string values;
      for (double x : eigenvalues) values += (values.empty() ? "" : ", ") + fmt::format("{:.6g}", x);
      return fmt::format("its subdominant eigenvalues are {}, where a surface differentiable in the face's parameters "
                         "needs {:.6g} (the parameters' scale per step)",
                         values, scale);
    }
  return {};
}

LimitStencils SchemeLimits::stencils(const Level& level) { return stencils(level, impl_->options.first_step); }

LimitStencils SchemeLimits::stencils(const Level& level, int step) {
  const std::vector<LimitRows> rows = impl_->all_rows(level, step, nullptr);
  LimitStencils out;
  out.position.source_count = level.vertex_count;
  out.exact.assign(rows.size(), 0);
  for (size_t v = 0; v < rows.size(); ++v) {
    for (const auto& [s, w] : rows[v].position) out.position.indices.push_back(s), out.position.weights.push_back(w);
    out.position.offsets.push_back(Index(out.position.indices.size()));
    out.exact[v] = rows[v].exact ? 1 : 0;
    if (!rows[v].exact && out.first_approximate == kNone) {
      out.first_approximate = Index(v);
      out.first_reason = rows[v].reason;
    }
    out.approximate += rows[v].exact ? 0 : 1;
  }
  return out;
}

LimitResult SchemeLimits::evaluate(const Level& level, std::span<const double> positions) {
  return evaluate(level, positions, {});
}

LimitResult SchemeLimits::evaluate(const Level& level, std::span<const double> positions,
                                   std::span<const double> weights) {
  Impl& I = *impl_;
  const Index V = level.vertex_count;
  if (positions.size() != size_t(3 * V))
    throw Error(fmt::format("limit positions: {} coordinates given for {} vertices", positions.size(), V));
  if (!weights.empty() && weights.size() != size_t(V))
    throw Error(fmt::format("limit positions: {} weights given for {} vertices", weights.size(), V));
  std::vector<std::uint8_t> refined(size_t(V), 0);
  const std::vector<LimitRows> rows = I.all_rows(level, I.options.first_step, &refined);
  LimitResult r;
  r.positions.assign(size_t(3 * V), 0.0);
  r.normals.assign(size_t(3 * V), 0.0);
  r.exact.assign(size_t(V), 0);
  r.normal_exact.assign(size_t(V), 0);
  tbb::parallel_for(Index(0), V, [&](Index v) {
    const LimitRows& l = rows[size_t(v)];
    Vec3 p = applied(l.position, positions);
    const double W = weights.empty() ? 1.0 : applied_scalar(l.position, weights);
    if (!weights.empty())
      for (double& c : p) c /= W;
    const bool normal_exact = l.exact && l.normal_exact && l.directions.size() >= 2;
    const Vec3 n = normal_exact ? normal_of(l, positions, weights, p, W) : Vec3{0, 0, 0};
    for (int i = 0; i < 3; ++i) {
      r.positions[size_t(3 * v + i)] = p[size_t(i)];
      r.normals[size_t(3 * v + i)] = n[size_t(i)];
    }
    r.exact[size_t(v)] = l.exact ? 1 : 0;
    r.normal_exact[size_t(v)] = normal_exact ? 1 : 0;
  });
  for (Index v = 0; v < V; ++v) {
    if (!r.exact[size_t(v)]) ++r.approximate;
    if (r.exact[size_t(v)] && !r.normal_exact[size_t(v)]) ++r.approximate_normals;
    r.refined_vertices += refined[size_t(v)];
  }
  // Estimated normals: from the limit points of the vertex and its neighbours, sector by
  // sector, which is closer to the limit surface than the control points.
  for (Index v = 0; v < V; ++v) {
    if (r.normal_exact[size_t(v)] || level.incident_face_count(v) == 0) continue;
    Vec3 n{0, 0, 0};
    const Vec3 c = point(r.positions, v);
    const auto faces = level.ring_faces(v);
    for (size_t i = 0; i < faces.size(); ++i) {
      const auto corners = level.face(faces[i]);
      const int k = int(corners.size());
      const int at = level.vertex_face_corner[size_t(level.vertex_face_offsets[v]) + i];
      const Vec3 a = point(r.positions, corners[size_t((at + 1) % k)]), b = point(r.positions, corners[size_t((at + k - 1) % k)]);
      const Vec3 x = cross({a[0] - c[0], a[1] - c[1], a[2] - c[2]}, {b[0] - c[0], b[1] - c[1], b[2] - c[2]});
      n[0] += x[0], n[1] += x[1], n[2] += x[2];
    }
    const Vec3 u = normalised(n);
    if (u[0] != 0 || u[1] != 0 || u[2] != 0)
      for (int i = 0; i < 3; ++i) r.normals[size_t(3 * v + i)] = u[size_t(i)];
  }
  r.configurations = int(I.cache.size());
  r.approximate_reasons = I.reasons;
  return r;
}

LimitResult limit_positions(const Scheme& scheme, const Level& level, std::span<const double> positions,
                            const LimitOptions& options) {
  std::shared_ptr<const Scheme> with_rim;
  SchemeLimits e(scheme_for_cut_rims(scheme, level, with_rim), options);
  return e.evaluate(level, positions);
}

}  // namespace subdiv
