#include "framework/limit/sqrt3_limit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <optional>
#include <fmt/format.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/analysis/surface/local_patch.h"
#include "framework/engine/ghost_rings.h"
#include "framework/engine/refiner.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/step_matrix.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

using Bary = std::array<double, 3>;
using Lattice = std::array<int, 3>;  // 3 b, a point of the triadic lattice (sums to 3)

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The current cut: a level around the point's face, and its vertices in the level it was cut from.
struct Cut {
  Level level;
  std::vector<Index> original;
  Index face = kNone;
};

Cut cut_around(const Level& L, Index face, int radius) {
  Extracted e = extract_neighbourhood(L, CentreKind::Face, face, radius);
  Cut c;
  c.level = std::move(e.level);
  c.original = std::move(e.original);
  for (size_t f = 0; f < e.face_original.size(); ++f)
    if (e.face_original[f] == face) c.face = Index(f);
  return c;
}

// The point in its triangle: barycentric coordinates from the face's corner 0 (b[1], b[2] are
// its (s, t)), and d(s, t)/d(u, v) carried as 3^-k times its value after k double steps, so
// that derivative rows stay of order one (step_matrix.h).
struct TrianglePoint {
  Bary b{1, 0, 0};
  Jacobian jacobian{{{1, 0}, {0, 1}}};
};

// Barycentric coordinates in the frame of triangle f of the base cut: its corners, and the
// far corner of each neighbour across its edges, unfolded affinely (a + b - c).
std::vector<Bary> frame_coordinates(const Level& L, Index f) {
  std::vector<Bary> at(size_t(L.vertex_count), Bary{kNan, kNan, kNan});
  const auto fv = L.face(f);
  for (int k = 0; k < 3; ++k) {
    Bary e{0, 0, 0};
    e[size_t(k)] = 1;
    at[size_t(fv[size_t(k)])] = e;
  }
  const auto fe = L.face_edge_list(f);
  for (int k = 0; k < 3; ++k) {
    const Index e = fe[size_t(k)];
    const Index g = L.edge_faces[size_t(2 * e)] == f ? L.edge_faces[size_t(2 * e + 1)] : L.edge_faces[size_t(2 * e)];
    if (g == kNone || L.face_size(g) != 3) continue;
    for (Index w : L.face(g)) {
      if (w == fv[size_t(k)] || w == fv[size_t((k + 1) % 3)]) continue;
      Bary x{0, 0, 0};
      x[size_t(k)] = 1, x[size_t((k + 1) % 3)] = 1, x[size_t((k + 2) % 3)] = -1;
      at[size_t(w)] = x;
    }
  }
  return at;
}

// Where the children of a step lie: a vertex child at its parent vertex, a face child at the
// centroid of its parent face (the parameterisation, whatever the rules' weights).
std::vector<Bary> child_coordinates(const Level& parent, const std::vector<Bary>& at, const ChildOrigins& o) {
  std::vector<Bary> out(o.kind.size(), Bary{kNan, kNan, kNan});
  for (size_t v = 0; v < o.kind.size(); ++v) {
    if (o.kind[v] == OriginKind::Vertex) {
      out[v] = at[size_t(o.parent[v])];
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

// A triangle of the triadic split: its corners on the lattice, in the child face's order.
// `up`: like the parent (corner m = base + e_q[m]); else turned (corner m = top - e_q[m]).
struct ChildTriangle {
  Index face = kNone;
  bool up = true;
  Lattice anchor{};  // base (up) or top (turned)
  std::array<int, 3> q{};
};

std::optional<Lattice> on_lattice(const Bary& b) {
  Lattice l{};
  for (size_t i = 0; i < 3; ++i) {
    const double x = 3 * b[i];
    if (!std::isfinite(x) || std::fabs(x - std::round(x)) > 1e-9 || std::round(x) < 0) return std::nullopt;
    l[i] = int(std::round(x));
  }
  return l;
}

std::vector<ChildTriangle> triadic_children(const Level& level2, const std::vector<Bary>& at) {
  std::vector<ChildTriangle> out;
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
    ChildTriangle t;
    t.face = g;
    Lattice lo{}, hi{};
    for (size_t i = 0; i < 3; ++i) {
      lo[i] = std::min({c[0][i], c[1][i], c[2][i]});
      hi[i] = std::max({c[0][i], c[1][i], c[2][i]});
    }
    t.up = lo[0] + lo[1] + lo[2] == 2;
    if (!t.up && hi[0] + hi[1] + hi[2] != 4) throw Error("internal: a sqrt3 child triangle is not a cell of the triadic lattice");
    t.anchor = t.up ? lo : hi;
    for (size_t m = 0; m < 3; ++m) {
      int q = -1;
      for (int i = 0; i < 3; ++i)
        if (c[m][size_t(i)] != t.anchor[size_t(i)]) q = i;
      t.q[m] = q;
    }
    out.push_back(t);
  }
  if (out.size() != 9)
    throw Error(fmt::format("internal: two sqrt3 steps made {} triangles in a face, not the 9 of a triadic split", out.size()));
  return out;
}

// The point's barycentric coordinates in child t. Each is one subtraction from 3 b_q, so a
// coordinate that is small keeps its digits; the largest is then 1 less the other two.
Bary in_child(const ChildTriangle& t, const Bary& b) {
  Bary beta{};
  for (size_t m = 0; m < 3; ++m) {
    const double x = 3 * b[size_t(t.q[m])];
    beta[m] = t.up ? x - t.anchor[size_t(t.q[m])] : t.anchor[size_t(t.q[m])] - x;
  }
  const size_t k = size_t(std::max_element(beta.begin(), beta.end()) - beta.begin());
  beta[k] = 1 - beta[(k + 1) % 3] - beta[(k + 2) % 3];
  return beta;
}

// d(beta_m)/d(s, t) of the parent, over 3: the gradient of b_q, negated for a turned triangle.
std::array<double, 2> gradient(const ChildTriangle& t, size_t m) {
  constexpr double kGrad[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  const double sign = t.up ? 1 : -1;
  return {sign * kGrad[t.q[m]][0], sign * kGrad[t.q[m]][1]};
}

// Two steps as one matrix: rows the kept vertices of level 2, columns the cut's vertices.
StepMatrix two_steps(const Hierarchy& h, const std::vector<Index>& rows, Index source_count) {
  StepMatrix m;
  m.source_count = source_count;
  m.scale = 3;
  const StencilTable& first = h.stencils[0];
  const StencilTable& second = h.stencils[1];
  std::vector<double> acc(size_t(source_count), 0.0);
  std::vector<Index> touched;
  for (Index r : rows) {
    for (Index e = second.offsets[size_t(r)]; e < second.offsets[size_t(r) + 1]; ++e) {
      const Index mid = second.indices[size_t(e)];
      const double w = second.weights[size_t(e)];
      for (Index x = first.offsets[size_t(mid)]; x < first.offsets[size_t(mid) + 1]; ++x) {
        const Index c = first.indices[size_t(x)];
        if (acc[size_t(c)] == 0) touched.push_back(c);
        acc[size_t(c)] += w * first.weights[size_t(x)];
      }
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for (Index c : touched) {
      if (acc[size_t(c)] != 0) m.columns.push_back(c), m.weights.push_back(acc[size_t(c)]);
      acc[size_t(c)] = 0;
    }
    touched.clear();
    m.offsets.push_back(Index(m.columns.size()));
  }
  return m;
}

bool extraordinary_corner(const Level& L, Index face) {
  for (Index v : L.face(face))
    if (L.incident_face_count(v) != 6) return true;
  return false;
}

}  // namespace

std::string sqrt3_limit_unsupported(const Level& base) {
  for (Index v = 0; v < base.vertex_count; ++v)
    if (base.on_boundary(v))
      return "the mesh has a boundary: sqrt3 schemes trisect boundary edges every second step, and the limit's "
             "parameterisation along a boundary is not defined yet; close the mesh, or use a primal scheme";
  for (float s : base.edge_sharpness)
    if (s > 0) return "the mesh has sharp or semi-sharp edges: evaluation of sqrt3 schemes with creases is not done yet";
  for (float s : base.vertex_sharpness)
    if (s > 0) return "the mesh has sharp vertices: evaluation of sqrt3 schemes with corners is not done yet";
  if (!base.face_hole.empty())
    for (auto h : base.face_hole)
      if (h) return "the mesh has holes: evaluation of sqrt3 schemes next to holes is not done yet";
  return {};
}

Sqrt3Limit::Sqrt3Limit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options,
                       SchemeLimits& limits)
    : scheme_(scheme), base_(base), options_(options), limits_(limits) {
  // Two steps lose `loss` rings of the cut (in its own rings, an over-estimate for the second
  // step's smaller ones); the next cut, `radius` rings of triangles a third the size, must lie
  // in what is left: radius / 3 + 1 <= radius - loss.
  const SchemeRun run{&scheme, 2};
  double loss = 0;
  for (double x : ring_loss_per_level(std::span<const SchemeRun>(&run, 1))) loss += std::max(x, 0.0);
  radius_ = std::max(5, int(std::ceil(1.5 * (loss + 1))) + 1);
}

std::vector<Index> Sqrt3Limit::reads(const FacePoint& p) const { return cut_around(base_, p.face, radius_).original; }

LimitSample Sqrt3Limit::evaluate(const FacePoint& p0, const std::vector<double>& first_values, int channels,
                                 int derivatives, Rows* rows_out) const {
  Cut cut = cut_around(base_, p0.face, radius_);
  TrianglePoint q;
  q.b = {1 - p0.st[0] - p0.st[1], p0.st[0], p0.st[1]};
  q.jacobian = p0.jacobian;
  std::deque<StepMatrix> owned;
  std::vector<const StepMatrix*> path;
  std::vector<double> values = first_values;
  int stop = kRoundOffSteps;
  const int give_up = 24 * kRoundOffSteps;  // past the smallest double's distance to a vertex (3^-680)
  std::string mask_error;
  for (int step = 0;; ++step) {
    if (extraordinary_corner(cut.level, cut.face)) stop = std::max(stop, step + kRoundOffSteps);
    const int k = int(std::max_element(q.b.begin(), q.b.end()) - q.b.begin());
    // Exactly at a corner: the other two coordinates are 0 (the largest, 1 less them, may
    // round to 1 for a point 1e-300 away, which is not at the corner).
    const bool at_vertex = q.b[size_t((k + 1) % 3)] == 0 && q.b[size_t((k + 2) % 3)] == 0;
    if (at_vertex || step >= stop) {
      FacePoint corner;
      corner.face = cut.face;
      corner.st = {q.b[1], q.b[2]};
      CornerRows rows;
      if (corner_rows(limits_, cut.level, corner, k, 0, true, rows, mask_error)) {
        LimitSample out;
        out.steps = step;
        out.position = applied(rows.position, values, channels);
        if (derivatives >= 1 && !rows.ds.empty()) {
          const auto& J = q.jacobian;
          auto row = [&](int d) {
            std::vector<double> r(rows.ds.size());
            for (size_t i = 0; i < r.size(); ++i) r[i] = J[0][size_t(d)] * rows.ds[i] + J[1][size_t(d)] * rows.dt[i];
            return pulled_back(std::move(r), path);
          };
          std::vector<double> u = row(0), v = row(1);
          out.du = applied(u, first_values, channels);
          out.dv = applied(v, first_values, channels);
          out.has_derivatives = true;
          if (rows_out) rows_out->du = std::move(u), rows_out->dv = std::move(v);
        }
        return out;
      }
    }
    if (step >= give_up)
      throw Error(fmt::format("internal: the point's nearest vertex has no limit mask after {} double sqrt3 steps{}{}", step,
                              mask_error.empty() ? "" : ": ", mask_error));
    RefineOptions ro;
    ro.levels = 2;
    ro.features = options_.features;
    const Hierarchy h = refine(scheme_, cut.level, ro);
    const std::vector<Bary> at1 = child_coordinates(cut.level, frame_coordinates(cut.level, cut.face), h.origins[0]);
    const std::vector<Bary> at2 = child_coordinates(h.levels[1], at1, h.origins[1]);
    const std::vector<ChildTriangle> children = triadic_children(h.levels[2], at2);
    // The child holding the point: every coordinate >= 0, else the least outside (round-off).
    size_t best = 0;
    double best_min = -std::numeric_limits<double>::infinity();
    Bary beta{};
    for (size_t i = 0; i < children.size(); ++i) {
      const Bary x = in_child(children[i], q.b);
      const double lowest = std::min({x[0], x[1], x[2]});
      if (lowest > best_min) best_min = lowest, best = i, beta = x;
    }
    const ChildTriangle& t = children[best];
    TrianglePoint next;
    next.b = beta;
    for (size_t m = 1; m < 3; ++m) {
      const auto g = gradient(t, m);
      for (size_t c = 0; c < 2; ++c) next.jacobian[m - 1][c] = g[0] * q.jacobian[0][c] + g[1] * q.jacobian[1][c];
    }
    Cut child = cut_around(h.levels[2], t.face, radius_);
    owned.push_back(two_steps(h, child.original, cut.level.vertex_count));
    path.push_back(&owned.back());
    std::vector<double> moved(size_t(owned.back().rows()) * size_t(channels));
    owned.back().apply(values, moved, channels);
    values.swap(moved);
    cut = std::move(child);
    q = next;
  }
}

}  // namespace subdiv
