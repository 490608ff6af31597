#include "framework/limit/sqrt3_limit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <fmt/format.h>

#include "framework/analysis/surface/local_patch.h"
#include "framework/engine/ghost_rings.h"
#include "framework/features/sharpness.h"
#include "framework/limit/corner_limit.h"
#include "framework/limit/sqrt3_nodes.h"
#include "framework/limit/step_matrix.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

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


// Makes a second-derivative row over a node's labels annihilate the node's sampled affine
// functions (Sqrt3Node::affine), as it does in exact arithmetic. Pulled back with the factor
// 9 per double step, the row's part along them grows by 9 λ₁ = 3 per double step, so its
// rounding would grow to 3^43 ε over a descent; removed at each node, it stays at ε. The part
// is moved onto the face's corners, at (0, 0), (1, 0), (0, 1).
void drop_affine_part(std::vector<double>& row, const Sqrt3Node& node) {
  if (!node.affine) return;
  double m0 = 0, m1 = 0, m2 = 0;
  for (size_t l = 0; l < row.size(); ++l) {
    m0 += row[l];
    m1 += row[l] * node.affine->at[l][0];
    m2 += row[l] * node.affine->at[l][1];
  }
  const auto& c = node.affine->corners;
  row[size_t(c[0])] -= m0 - m1 - m2;
  row[size_t(c[1])] -= m1;
  row[size_t(c[2])] -= m2;
}

}  // namespace

int sqrt3_single_step_levels(const Level& base) {
  // Boundaries and sharp edges follow Kobbelt's rules (kept in the first step, trisected in
  // the second: the triadic split, sqrt3_nodes.h). Sharpness decays by one per step, so an
  // edge of sharpness s in (2k, 2k + 1] is kept in the first step of pair k and flipped in
  // its second; after 2k + 2 steps it is smooth. Tagged vertices change rules only.
  int levels = 0;
  for (Index e = 0; e < Index(base.edge_sharpness.size()); ++e) {
    const float s = base.edge_sharpness[size_t(e)];
    if (s <= 0 || s >= kInfinitelySharp || base.edge_on_boundary(e)) continue;
    const double parity = std::fmod(double(s), 2.0);
    if (parity > 0 && parity <= 1) levels = std::max(levels, 2 * int(std::ceil(double(s) / 2)));
  }
  return levels;
}

Sqrt3Limit::Sqrt3Limit(const Scheme& scheme, const Level& base, const LimitSurfaceOptions& options,
                       SchemeLimits& limits)
    : scheme_(scheme), base_(base) {
  // Two steps lose `loss` rings of the cut (in its own rings, an over-estimate for the second
  // step's smaller ones); the next cut, `radius` rings of triangles a third the size, must lie
  // in what is left: radius / 3 + 1 <= radius - loss.
  const SchemeRun run{&scheme, 2};
  double loss = 0;
  for (double x : ring_loss_per_level(std::span<const SchemeRun>(&run, 1))) loss += std::max(x, 0.0);
  radius_ = std::max(5, int(std::ceil(1.5 * (loss + 1))) + 1);
  nodes_ = std::make_unique<Sqrt3Nodes>(scheme, options.features, radius_, limits);
  entries_.resize(size_t(base.face_count()));
}

Sqrt3Limit::~Sqrt3Limit() = default;

const Sqrt3Limit::Entry& Sqrt3Limit::entry(Index face) const {
  {
    std::lock_guard lock(entry_mutex_);
    if (entries_[size_t(face)]) return *entries_[size_t(face)];
  }
  const Cut cut = cut_around(base_, face, radius_);
  auto e = std::make_unique<Entry>();
  std::vector<Index> order;
  e->node = nodes_->intern(cut.level, cut.face, order);
  for (Index v : order) e->vertices.push_back(cut.original[size_t(v)]);
  std::lock_guard lock(entry_mutex_);
  if (!entries_[size_t(face)]) entries_[size_t(face)] = std::move(e);
  return *entries_[size_t(face)];
}

std::vector<Index> Sqrt3Limit::reads(const FacePoint& p) const { return entry(p.face).vertices; }

LimitSample Sqrt3Limit::evaluate(const FacePoint& p0, const std::vector<double>& first_values, int channels,
                                 int derivatives, Rows* rows_out) const {
  int id = entry(p0.face).node;
  TrianglePoint q;
  q.b = {1 - p0.st[0] - p0.st[1], p0.st[0], p0.st[1]};
  q.jacobian = p0.jacobian;
  std::vector<const StepMatrix*> path;
  std::vector<const Sqrt3Node*> path_nodes;  // the node each step of the path starts from
  std::vector<double> values = first_values;
  // Second derivatives are Hölder continuous only: their descent goes further.
  const int round_off = derivatives >= 2 ? kSecondOrderSteps : kRoundOffSteps;
  int stop = round_off;
  const int give_up = 24 * kRoundOffSteps;  // past the smallest double's distance to a vertex (3^-680)
  NoLimitMask mask_error;
  int deferred = 0;  // double steps taken past a corner whose derivatives a nearby boundary took away
  for (int step = 0;; ++step) {
    const Sqrt3Node& node = nodes_->expanded(id);
    if (node.extraordinary) stop = std::max(stop, step + round_off);
    const int k = int(std::max_element(q.b.begin(), q.b.end()) - q.b.begin());
    // Exactly at a corner: the other two coordinates are 0 (the largest, 1 less them, may
    // round to 1 for a point 1e-300 away, which is not at the corner).
    const bool at_vertex = q.b[size_t((k + 1) % 3)] == 0 && q.b[size_t((k + 2) % 3)] == 0;
    if (at_vertex || step >= stop) {
      const CornerRows* rows = nodes_->corner(id, k, mask_error);
      // Next to a boundary the corner's derivatives wait for a level where it is far enough
      // from it (sqrt3_nodes.cpp); a point within round-off of the boundary stops without.
      if (rows && derivatives >= 1 && node.corner_deferred[size_t(k)] && deferred < round_off) {
        ++deferred;
        rows = nullptr;
      }
      // At the vertex itself, which keeps its configuration from double step to double step, a
      // failed analysis fails at every level (limit_surface.cpp's descent says the same).
      if (!rows && at_vertex && !mask_error.verdict.empty()) throw Error(no_limit_mask(scheme_, 2 * step, mask_error));
      if (rows && derivatives >= 1 && !rows->no_derivatives.empty())
        throw Error(not_c1_derivatives(scheme_, rows->no_derivatives));
      if (rows) {
        LimitSample out;
        out.steps = step;
        out.position = applied(rows->position, values, channels);
        if (derivatives >= 1 && !rows->ds.empty()) {
          const auto& J = q.jacobian;
          FirstDerivativeRows d = first_derivative_rows(rows->ds, rows->dt, J, path);
          out.du = applied(d.du, first_values, channels);
          out.dv = applied(d.dv, first_values, channels);
          out.has_derivatives = true;
          if (rows_out) rows_out->du = std::move(d.du), rows_out->dv = std::move(d.dv);
        }
        if (derivatives >= 2 && out.has_derivatives && !rows->dss.empty()) {
          // The chain rule at the corner, then one step back at a time (drop_affine_part).
          SecondDerivativeRows d = second_derivative_rows(rows->dss, rows->dst, rows->dtt, q.jacobian, {});
          std::vector<double>* second[] = {&d.duu, &d.duv, &d.dvv};
          for (size_t j = path.size(); j-- > 0;) {
            pull_back_rows(second, std::span(&path[j], 1), 2);
            for (std::vector<double>* r : second) drop_affine_part(*r, *path_nodes[j]);
          }
          out.duu = applied(d.duu, first_values, channels);
          out.duv = applied(d.duv, first_values, channels);
          out.dvv = applied(d.dvv, first_values, channels);
          out.has_second_derivatives = true;
          if (rows_out) rows_out->duu = std::move(d.duu), rows_out->duv = std::move(d.duv), rows_out->dvv = std::move(d.dvv);
        }
        return out;
      }
    }
    if (step >= give_up && !mask_error.failure.empty()) throw Error(no_limit_mask(scheme_, 2 * step, mask_error));
    if (step >= give_up)
      throw Error(fmt::format("internal: the point's nearest vertex has no limit mask after {} double sqrt3 steps{}{}", step,
                              mask_error.verdict.empty() ? "" : ": ", mask_error.verdict));
    // The child holding the point: every coordinate >= 0, else the least outside (round-off).
    size_t best = 0;
    double best_min = -std::numeric_limits<double>::infinity();
    Bary beta{};
    for (size_t i = 0; i < node.children.size(); ++i) {
      const Bary x = in_child(node.children[i], q.b);
      const double lowest = std::min({x[0], x[1], x[2]});
      if (lowest > best_min) best_min = lowest, best = i, beta = x;
    }
    const TriadicChild& t = node.children[best];
    auto advance = [&](TrianglePoint& x, const Bary& b) {
      TrianglePoint next;
      next.b = b;
      for (int m = 1; m < 3; ++m) {
        const auto g = child_gradient(t, m);
        for (size_t c = 0; c < 2; ++c) next.jacobian[size_t(m - 1)][c] = g[0] * x.jacobian[0][c] + g[1] * x.jacobian[1][c];
      }
      x = next;
    };
    advance(q, beta);
    // A self-similar run (towards a vertex the point is near): the same node and child again
    // and again. Its length follows from the point alone; the run is taken with the step's
    // powers, one product per binary digit of its length (as the primal evaluator does).
    // A point exactly at the vertex (at_vertex) stays there; it steps only until the vertex's
    // neighbourhood is a known configuration. Elsewhere than next to an extraordinary vertex
    // a run stops where the descent does (`stop`).
    int run = 1;
    if (node.child_node[best] == id && !at_vertex) {
      for (;;) {
        size_t again = 0;
        double again_min = -std::numeric_limits<double>::infinity();
        Bary x{};
        for (size_t i = 0; i < node.children.size(); ++i) {
          const Bary y = in_child(node.children[i], q.b);
          const double lowest = std::min({y[0], y[1], y[2]});
          if (lowest > again_min) again_min = lowest, again = i, x = y;
        }
        if (again != best || run >= (1 << Sqrt3Nodes::kPowers) - 1 || step + run >= give_up ||
            (!node.extraordinary && step + run >= stop))
          break;
        advance(q, x);
        ++run;
      }
    }
    if (node.extraordinary) stop = std::max(stop, step + run - 1 + round_off);
    if (run == 1) {
      const StepMatrix& M = node.child_matrix[best];
      path.push_back(&M);
      path_nodes.push_back(&node);
      std::vector<double> moved(size_t(M.rows()) * size_t(channels));
      M.apply(values, moved, channels);
      values.swap(moved);
    } else {
      // Applied to the values less those of label 0 (added back after): the rows of a power
      // sum to one only to round-off that grows with the power, which then multiplies the small
      // differences of a cut 3^-k across instead of the values themselves.
      const Sqrt3Node::Powers& P = nodes_->powers(id, int(best), derivatives >= 2);
      for (int j = 0; j < Sqrt3Nodes::kPowers; ++j) {
        if (!(run >> j & 1)) continue;
        const StepMatrix& M = P.forward[size_t(j)];
        path.push_back(&M);
        path_nodes.push_back(&node);
        const std::vector<double> base(values.begin(), values.begin() + channels);
        for (size_t i = 0; i < values.size(); ++i) values[i] -= base[i % size_t(channels)];
        std::vector<double> moved(size_t(M.rows()) * size_t(channels));
        M.apply(values, moved, channels);
        for (size_t i = 0; i < moved.size(); ++i) moved[i] += base[i % size_t(channels)];
        values.swap(moved);
      }
    }
    id = node.child_node[best];
    step += run - 1;
  }
}

}  // namespace subdiv
