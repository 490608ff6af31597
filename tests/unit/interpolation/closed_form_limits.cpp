#include "closed_form_limits.h"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "framework/interpolation/limit_rows.h"
#include "framework/refine/child_tags.h"

namespace subdiv::test {
namespace {

using detail::LimitRow;

// How a closed form treats a vertex's features.
struct FeatureView {
  const Level& level;
  FeatureContexts fc;
  FeatureView(const Level& l, const FeatureOptions& o) : level(l), fc(classify_features(l, o)) {}

  // Empty: the vertex has no semi-sharp feature (its rule is the same at every level).
  std::string semi_sharp(Index v) const {
    if (is_semi_sharp(fc.vertex_sharpness[v]))
      return fmt::format("vertex {} has semi-sharp corner sharpness {}", v, fc.vertex_sharpness[v]);
    for (Index e : level.ring_edges(v))
      if (is_semi_sharp(fc.edge_sharpness[e]))
        return fmt::format("vertex {} has a semi-sharp edge to vertex {} (sharpness {})", v, level.other_end(e, v),
                           fc.edge_sharpness[e]);
    return {};
  }
};

// The rows every closed form shares. Returns true when the vertex was handled (a corner
// or a crease vertex); false leaves a smooth or dart vertex to the caller.
bool feature_row(const FeatureView& view, Index v, LimitRow& row) {
  const VertexContext& c = view.fc.vertices[v];
  if (c.parent == Context::Corner) {
    row.add(v, 1.0);
    return true;
  }
  if (c.parent == Context::Crease) {
    const auto ring = view.level.ring_edges(v);
    row.add(view.level.other_end(ring[c.parent_crease[0]], v), 1.0 / 6);
    row.add(v, 2.0 / 3);
    row.add(view.level.other_end(ring[c.parent_crease[1]], v), 1.0 / 6);
    return true;
  }
  return false;
}

std::string boundary_none(const Level& level, const FeatureOptions& o, const std::string& who) {
  if (o.boundary != BoundaryInterpolation::None) return {};
  for (Index v = 0; v < level.vertex_count; ++v)
    if (level.on_boundary(v))
      return fmt::format("{}: boundary vertex {} under boundary interpolation 'none' has no closed-form limit; "
                         "use edges or edges-and-corners", who, v);
  return {};
}

std::string dart_message(const std::string& who, Index v) {
  return fmt::format("{}: vertex {} is a dart (one sharp edge); its limit has no closed form here. "
                     "The engine's analysed masks cover it", who, v);
}

}  // namespace

StencilTable CatmullClarkLimit::stencils_at(const Level& level, int) const {
  const std::string who = name();
  if (auto why = boundary_none(level, features_, who); !why.empty()) throw Error(why);
  const FeatureView view(level, features_);
  return detail::build_limit_rows(level.vertex_count, level.vertex_count, [&](Index v, LimitRow& row) -> std::string {
    if (auto why = view.semi_sharp(v); !why.empty()) return who + ": " + why + "; it has no closed-form limit";
    if (feature_row(view, v, row)) return {};
    if (view.fc.vertices[v].parent == Context::Dart) return dart_message(who, v);
    // (n (n - 1) v + 2 sum e_j + 4 sum c_j) / (n (n + 5)), c_j the centroids of the faces.
    const int n = level.valence(v);
    const double d = double(n) * (n + 5);
    row.add(v, n * (n - 1.0) / d);
    for (Index e : level.ring_edges(v)) row.add(level.other_end(e, v), 2.0 / d);
    for (Index f : level.ring_faces(v)) {
      const auto corners = level.face(f);
      for (Index u : corners) row.add(u, 4.0 / d / double(corners.size()));
    }
    return {};
  });
}

double loop_beta(LoopBeta variant, int n) {
  if (variant == LoopBeta::Warren) return n == 3 ? 3.0 / 16 : 3.0 / (8.0 * n);
  const double c = 3.0 / 8 + std::cos(2 * std::numbers::pi / n) / 4;
  return (5.0 / 8 - c * c) / n;
}

std::string LoopLimit::name() const {
  return beta_ == LoopBeta::Loop ? "Loop closed form (Loop's beta)" : "Loop closed form (Warren's beta)";
}

StencilTable LoopLimit::stencils_at(const Level& level, int) const {
  const std::string who = name();
  if (auto why = boundary_none(level, features_, who); !why.empty()) throw Error(why);
  const FeatureView view(level, features_);
  return detail::build_limit_rows(level.vertex_count, level.vertex_count, [&](Index v, LimitRow& row) -> std::string {
    if (auto why = view.semi_sharp(v); !why.empty()) return who + ": " + why + "; it has no closed-form limit";
    for (Index f : level.ring_faces(v))
      if (level.face_size(f) != 3)
        return fmt::format("{}: face {} at vertex {} has {} sides; Loop's limit mask needs triangles", who, f, v,
                           level.face_size(f));
    if (feature_row(view, v, row)) return {};
    if (view.fc.vertices[v].parent == Context::Dart) return dart_message(who, v);
    const int n = level.valence(v);
    const double gamma = 3.0 / (3.0 + 8.0 * n * loop_beta(beta_, n));
    row.add(v, gamma);
    for (Index e : level.ring_edges(v)) row.add(level.other_end(e, v), (1 - gamma) / n);
    return {};
  });
}

StencilTable Sqrt3Limit::stencils_at(const Level& level, int) const {
  const std::string who = name();
  const FeatureView view(level, features_);
  return detail::build_limit_rows(level.vertex_count, level.vertex_count, [&](Index v, LimitRow& row) -> std::string {
    if (auto why = view.semi_sharp(v); !why.empty()) return who + ": " + why + "; it has no closed-form limit";
    for (Index f : level.ring_faces(v))
      if (level.face_size(f) != 3)
        return fmt::format("{}: face {} at vertex {} has {} sides; sqrt(3) needs triangles", who, f, v,
                           level.face_size(f));
    const Context c = view.fc.vertices[v].parent;
    if (c == Context::Corner) {
      row.add(v, 1.0);
      return {};
    }
    if (c != Context::Smooth)
      return fmt::format("{}: vertex {} is on a boundary or crease; sqrt(3)'s curve limit (trisected every "
                         "second step) is left to the engine's analysed masks", who, v);
    const int n = level.valence(v);
    const double a = (4 - 2 * std::cos(2 * std::numbers::pi / n)) / 9, b = 3 * a / (1 + 3 * a);
    row.add(v, 1 - b);
    for (Index e : level.ring_edges(v)) row.add(level.other_end(e, v), b / n);
    return {};
  });
}

}  // namespace subdiv::test
