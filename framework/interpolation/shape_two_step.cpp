#include "framework/interpolation/shape_two_step.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "framework/interpolation/limit_rows.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// The vertex opposite v in quad ring face i of v.
Index diagonal(const Level& level, Index v, int i) {
  const Index f = level.ring_faces(v)[i];
  const int corner = level.vertex_face_corner[level.vertex_face_offsets[v] + i];
  return level.face(f)[(corner + 2) % 4];
}

std::string not_closed_quads(const Level& level, Index v) {
  if (level.on_boundary(v))
    return fmt::format("vertex {} is on the boundary; formula (2) of seed 001 holds on closed quad meshes", v);
  for (Index f : level.ring_faces(v))
    if (level.face_size(f) != 4)
      return fmt::format("face {} at vertex {} has {} sides; formula (2) of seed 001 needs quads", f, v,
                         level.face_size(f));
  if (level.vertex_sharp(v) > 0) return fmt::format("vertex {} is tagged sharp; formula (2) of seed 001 has no creases", v);
  for (Index e : level.ring_edges(v))
    if (level.edge_sharp(e) > 0)
      return fmt::format("the edge from vertex {} to {} is tagged sharp; formula (2) of seed 001 has no creases", v,
                         level.other_end(e, v));
  return {};
}

}  // namespace

void check_shape_lambda(std::span<const double> lambda, Index vertex_count, const std::string& what) {
  if (lambda.size() != 1 && lambda.size() != size_t(vertex_count))
    throw Error(fmt::format("{}: {} values for a mesh of {} vertices; give one value or one per vertex", what,
                            lambda.size(), vertex_count));
  for (size_t i = 0; i < lambda.size(); ++i) {
    const double l = lambda[i];
    if (!(l > kShapeLambdaMin && l <= kShapeLambdaMax)) {
      const std::string who = lambda.size() == 1 ? what : fmt::format("{} (vertex {})", what, i);
      throw Error(fmt::format("{}: lambda = {} is outside (7/20, 1]; seed 001's two-step Catmull-Clark converges "
                              "only for 0.35 < lambda <= 1", who, l));
    }
  }
}

ShapeTwoStepLimit::ShapeTwoStepLimit(double lambda) : lambda_{lambda} {
  check_shape_lambda(lambda_, 1);
}

ShapeTwoStepLimit::ShapeTwoStepLimit(std::vector<double> lambda_per_vertex) : lambda_(std::move(lambda_per_vertex)) {
  if (lambda_.empty()) throw Error("lambda: no values given");
  for (size_t i = 0; i < lambda_.size(); ++i) check_shape_lambda(std::span(&lambda_[i], 1), 1, fmt::format("lambda (vertex {})", i));
}

std::string ShapeTwoStepLimit::name() const {
  if (lambda_.size() == 1) return fmt::format("seed 001 formula (2), two-step Catmull-Clark, lambda = {}", lambda_[0]);
  return "seed 001 formula (2), two-step Catmull-Clark, lambda per vertex";
}

StencilTable ShapeTwoStepLimit::stencils_at(const Level& level, int) const {
  if (lambda_.size() != 1 && lambda_.size() != size_t(level.vertex_count))
    throw Error(fmt::format("seed 001 formula (2): {} lambda values for a mesh of {} vertices", lambda_.size(),
                            level.vertex_count));
  return detail::build_limit_rows(level.vertex_count, level.vertex_count,
                                  [&](Index v, detail::LimitRow& row) -> std::string {
    if (auto why = not_closed_quads(level, v); !why.empty()) return why;
    // (2): ((n^2 lambda + 7n/4) v + beta_n sum e_j + 3/10 beta_n sum f_j) / (n (n + 5)).
    const double n = level.valence(v), l = lambda(v);
    const double beta = n * (1 - l) * 10.0 / 13.0 + 5.0 / 2.0, d = n * (n + 5);
    row.add(v, (n * n * l + 7.0 * n / 4.0) / d);
    for (Index e : level.ring_edges(v)) row.add(level.other_end(e, v), beta / d);
    for (int i = 0; i < level.valence(v); ++i) row.add(diagonal(level, v, i), 3.0 / 10.0 * beta / d);
    return {};
  });
}

StencilTable shape_first_step(const Level& base, const ChildOrigins& origins, const StencilTable& engine_step,
                              std::span<const double> lambda, const FeatureOptions& features) {
  check_shape_lambda(lambda, base.vertex_count);
  if (engine_step.source_count != base.vertex_count || size_t(engine_step.row_count()) != origins.kind.size())
    throw Error("seed 001 first step: the stencil table does not belong to this level and its origins");
  const FeatureContexts fc = classify_features(base, features);
  auto lambda_of = [&](Index v) { return lambda.size() == 1 ? lambda[0] : lambda[v]; };
  StencilTable out;
  out.source_count = engine_step.source_count;
  out.offsets.reserve(engine_step.offsets.size());
  detail::LimitRow row;
  for (Index c = 0; c < engine_step.row_count(); ++c) {
    const Index v = origins.parent[c];
    const bool rewrite = origins.kind[c] == OriginKind::Vertex &&
                         (fc.vertices[v].parent == Context::Smooth || fc.vertices[v].parent == Context::Dart);
    if (!rewrite) {
      for (Index i = engine_step.offsets[c]; i < engine_step.offsets[c + 1]; ++i)
        out.indices.push_back(engine_step.indices[i]), out.weights.push_back(engine_step.weights[i]);
      out.offsets.push_back(Index(out.indices.size()));
      continue;
    }
    for (Index f : base.ring_faces(v))
      if (base.face_size(f) != 4)
        throw Error(fmt::format("seed 001 first step: face {} at vertex {} has {} sides; the shape rule needs quads",
                                f, v, base.face_size(f)));
    // v' = lambda v + (1 - lambda)(alpha E + (1 - alpha) F).
    const int n = base.valence(v);
    const double l = lambda_of(v);
    row.clear();
    row.add(v, l);
    for (Index e : base.ring_edges(v)) row.add(base.other_end(e, v), (1 - l) * kShapeAlpha / n);
    for (int i = 0; i < n; ++i) row.add(diagonal(base, v, i), (1 - l) * (1 - kShapeAlpha) / n);
    auto& terms = row.terms();
    std::sort(terms.begin(), terms.end());
    for (const auto& [s, w] : terms) out.indices.push_back(s), out.weights.push_back(w);
    out.offsets.push_back(Index(out.indices.size()));
  }
  return out;
}

ProgressiveResult shape_progressive_interpolation(const Level& closed_quads, std::span<const double> targets,
                                                  std::span<const double> lambda,
                                                  std::span<const std::uint8_t> moving,
                                                  const ProgressiveOptions& options) {
  check_shape_lambda(lambda, closed_quads.vertex_count);
  const ShapeTwoStepLimit limit = lambda.size() == 1 ? ShapeTwoStepLimit(lambda[0])
                                                     : ShapeTwoStepLimit(std::vector<double>(lambda.begin(), lambda.end()));
  return progressive_interpolation(limit, closed_quads, targets, moving, options);
}

}  // namespace subdiv
