#include "framework/interpolation/dual_limits.h"

#include <cmath>
#include <fmt/format.h>
#include <map>

#include "framework/features/dual_features.h"
#include "framework/interpolation/limit_rows.h"
#include "framework/scheme/scheme.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

RefineOptions with_levels(RefineOptions o, int levels, int step_offset) {
  o.levels = levels;
  o.first_step += step_offset;
  return o;
}

// The mean of the stencil rows of a face's vertices, merged by source.
std::map<Index, double> mean_row(const StencilTable& s, std::span<const Index> face) {
  std::map<Index, double> row;
  for (Index c : face)
    for (Index i = s.offsets[c]; i < s.offsets[c + 1]; ++i) row[s.indices[i]] += s.weights[i] / double(face.size());
  return row;
}

}  // namespace

std::vector<Index> vertex_faces_after_step(const Hierarchy& h) {
  const Level& parent = h.levels[0];
  const Level& child = h.levels[1];
  const ChildOrigins& o = h.origins[0];
  // The parent vertices a child vertex belongs to (at most two).
  auto owners = [&](Index c, Index out[2]) -> int {
    switch (o.kind[c]) {
      case OriginKind::Vertex: out[0] = o.parent[c]; return 1;
      case OriginKind::Edge: out[0] = parent.edge_vertices[2 * o.parent[c]], out[1] = parent.edge_vertices[2 * o.parent[c] + 1]; return 2;
      case OriginKind::Corner: out[0] = parent.face(o.parent[c])[o.local[c]]; return 1;
      case OriginKind::Face: return 0;
    }
    return 0;
  };
  std::vector<Index> vface(size_t(parent.vertex_count), kNone);
  for (Index f = 0; f < child.face_count(); ++f) {
    if (o.parent_face[f] != kNone) continue;
    const auto corners = child.face(f);
    Index common[2];
    int count = owners(corners[0], common);
    for (size_t i = 1; i < corners.size() && count > 0; ++i) {
      Index mine[2];
      const int m = owners(corners[i], mine);
      int kept = 0;
      for (int a = 0; a < count; ++a)
        for (int b = 0; b < m; ++b)
          if (common[a] == mine[b]) common[kept++] = common[a];
      count = kept;
    }
    if (count == 1) vface[common[0]] = f;
  }
  return vface;
}

DualCentroidLimit::DualCentroidLimit(std::shared_ptr<const Scheme> scheme, RefineOptions options)
    : scheme_(std::move(scheme)), options_(options) {}

std::string DualCentroidLimit::name() const { return fmt::format("V-face centroids of {} (Doo & Sabin 1978)", scheme_->name); }

StencilTable DualCentroidLimit::stencils_at(const Level& level, int step) const {
  RefineOptions one = options_;
  one.first_step = step;
  const Hierarchy h = refine(*scheme_, level, with_levels(one, 1, 0));
  const std::vector<Index> vface = vertex_faces_after_step(h);
  const StencilTable& s = h.stencils[0];
  const std::string who = name();
  return detail::build_limit_rows(level.vertex_count, level.vertex_count, [&](Index v, detail::LimitRow& row) -> std::string {
    if (level.on_boundary(v))
      return fmt::format("{}: vertex {} is on the boundary, where a dual scheme's V-face is open and no exact "
                         "mask is known; interpolate a closed mesh with it", who, v);
    // A corner's face corners collapse into one point that stays at the vertex at every level
    // (docs/features.md, "Creases in dual schemes"): the limit passes through it.
    if (dual_collapses(level, v)) return row.add(v, 1.0), std::string();
    if (dual_sharp_edge_count(level, v) > 0)
      return fmt::format("{}: vertex {} lies on a crease (an edge of sharpness >= 1), where the V-face is cut into "
                         "sectors and the limit point is the crease curve's, which is not computed for dual schemes "
                         "yet; interpolate the mesh without its creases, or with a primal scheme", who, v);
    if (vface[v] == kNone) return fmt::format("{}: vertex {} gets no V-face from one step of {}", who, v, scheme_->name);
    for (const auto& [source, w] : mean_row(s, h.levels[1].face(vface[v]))) row.add(source, w);
    return {};
  });
}

std::string dual_centroid_mismatch(const Scheme& scheme, const Level& level, const RefineOptions& options) {
  const Hierarchy h = refine(scheme, level, with_levels(options, 2, 0));
  const std::vector<Index> vface = vertex_faces_after_step(h);
  const Level& l1 = h.levels[1];
  const Level& l2 = h.levels[2];
  // The child face of each level-1 face.
  std::vector<Index> child_face(size_t(l1.face_count()), kNone);
  for (Index f = 0; f < l2.face_count(); ++f)
    if (h.origins[1].parent_face[f] != kNone) child_face[h.origins[1].parent_face[f]] = f;
  for (Index v = 0; v < level.vertex_count; ++v) {
    // Boundary, corner and crease vertices have no whole V-face (DualCentroidLimit says what
    // their limit is, or why it has none).
    if (level.on_boundary(v) || dual_collapses(level, v) || dual_sharp_edge_count(level, v) > 0) continue;
    const Index g = vface[v];
    if (g == kNone) return fmt::format("one step of {} makes no V-face around vertex {}", subdiv::quoted(scheme.name), v);
    if (child_face[g] == kNone)
      return fmt::format("one step of {} makes no child face inside the V-face of vertex {}", subdiv::quoted(scheme.name), v);
    const auto got = mean_row(h.stencils[1], l2.face(child_face[g]));
    const auto corners = l1.face(g);
    std::map<Index, double> want;
    for (Index c : corners) want[c] += 1.0 / double(corners.size());
    const std::map<Index, double>* both[] = {&got, &want};
    for (const std::map<Index, double>* m : both)
      for (const auto& [source, w] : *m) {
        const double a = got.count(source) ? got.at(source) : 0.0, b = want.count(source) ? want.at(source) : 0.0;
        if (std::abs(a - b) > 1e-12)
          return fmt::format("{} does not keep the centroid of the V-face of vertex {} (the face's child has "
                             "weight {:.15g} on its corner {}, the centroid {:.15g}), so V-face centroids are not "
                             "limit points", subdiv::quoted(scheme.name), v, a, source, b);
      }
  }
  return {};
}

}  // namespace subdiv
