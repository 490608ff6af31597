#include "framework/primvar/face_varying.h"

#include <algorithm>
#include <fmt/format.h>
#include <unordered_map>

#include "framework/engine/vertex_parameters.h"
#include "framework/features/sharpness.h"
#include "framework/primvar/crossing_step.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// The channel with one value per (vertex, value) pair, and each value's vertex.
struct Renumbered {
  FaceVaryingLevel level;
  std::vector<Index> vertex_of;  // per value
};

Renumbered renumber(const Level& vertices, const FaceVaryingLevel& base, int components) {
  if (base.indices.size() != vertices.face_vertices.size())
    throw Error(fmt::format("face-varying data: {} corner indices for {} face corners", base.indices.size(),
                            vertices.face_vertices.size()));
  const Index count = Index(base.values.size() / size_t(components));
  Renumbered out;
  std::unordered_map<std::uint64_t, Index> index_of;  // (vertex << 32 | value) -> new value
  index_of.reserve(base.indices.size());
  for (size_t c = 0; c < base.indices.size(); ++c) {
    const Index value = base.indices[c], vertex = vertices.face_vertices[c];
    if (value < 0 || value >= count)
      throw Error(fmt::format("face-varying data: face corner {} uses value {}, but there are {} values", c, value,
                              count));
    const std::uint64_t key = std::uint64_t(std::uint32_t(vertex)) << 32 | std::uint32_t(value);
    auto [it, added] = index_of.emplace(key, Index(out.vertex_of.size()));
    if (added) {
      out.vertex_of.push_back(vertex);
      out.level.values.insert(out.level.values.end(), base.values.begin() + size_t(value) * components,
                              base.values.begin() + size_t(value + 1) * components);
    }
    out.level.indices.push_back(it->second);
  }
  return out;
}

// The face-varying mesh: the vertex level's faces over the values.
Level value_mesh(const Level& vertices, const std::vector<Index>& indices, Index value_count) {
  Level level = build_level(value_count, vertices.face_offsets, indices);
  level.face_hole = vertices.face_hole;
  return level;
}

// The vertex mesh's sharpness on the value mesh: each face corner's edge and vertex.
void copy_sharpness(const Level& vertices, Level& values) {
  values.edge_sharpness.assign(size_t(values.edge_count()), 0.f);
  values.vertex_sharpness.assign(size_t(values.vertex_count), 0.f);
  for (Index f = 0; f < vertices.face_count(); ++f)
    for (int k = 0; k < vertices.face_size(f); ++k) {
      const Index e = vertices.face_edge_list(f)[k], fe = values.face_edge_list(f)[k];
      values.edge_sharpness[fe] = std::max(values.edge_sharpness[fe], vertices.edge_sharp(e));
      const Index v = vertices.face(f)[k], fv = values.face(f)[k];
      values.vertex_sharpness[fv] = std::max(values.vertex_sharpness[fv], vertices.vertex_sharp(v));
    }
}

// Vertices with a seam (an edge whose two faces use different values) at them.
std::vector<std::uint8_t> seam_vertices(const Level& vertices, const Level& values) {
  std::vector<Index> value_edge(size_t(vertices.edge_count()), kNone);
  std::vector<std::uint8_t> seam(size_t(vertices.vertex_count), 0);
  for (Index f = 0; f < vertices.face_count(); ++f)
    for (int k = 0; k < vertices.face_size(f); ++k) {
      const Index e = vertices.face_edge_list(f)[k], fe = values.face_edge_list(f)[k];
      if (value_edge[e] == kNone) value_edge[e] = fe;
      else if (value_edge[e] != fe)
        seam[vertices.edge_vertices[2 * e]] = seam[vertices.edge_vertices[2 * e + 1]] = 1;
    }
  return seam;
}

// What OpenSubdiv calls a value's span: the faces around its vertex that use it, and the
// edges inside that span (the value mesh's interior edges at the value).
struct Span {
  Index value = kNone;
  int faces = 0;
  bool disjoint = false;  // two separate fans, or cut by an infinitely sharp edge
  float semi_sharp = 0;   // the sharpest semi-sharp edge inside, 0 if none
};

Span span_of(const Level& values, Index value, int faces) {
  Span s{value, faces, values.non_manifold_vertex(value), 0.f};
  for (Index e : values.ring_edges(value)) {
    if (values.edge_face_count(e) < 2) continue;  // a seam or the boundary
    const float sharpness = values.edge_sharp(e);
    if (sharpness >= kInfinitelySharp) s.disjoint = true;
    else s.semi_sharp = std::max(s.semi_sharp, sharpness);
  }
  return s;
}

// The values at vertex v, in the order of v's faces, with their spans.
std::vector<Span> spans_at(const Level& vertices, const Level& values, Index v) {
  std::vector<std::pair<Index, int>> counts;
  for (int i = 0; i < vertices.incident_face_count(v); ++i) {
    const Index f = vertices.ring_faces(v)[i];
    const Index value = values.face(f)[vertices.vertex_face_corner[vertices.vertex_face_offsets[v] + i]];
    auto it = std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == value; });
    if (it == counts.end()) counts.emplace_back(value, 1);
    else ++it->second;
  }
  std::vector<Span> spans;
  for (const auto& [value, faces] : counts) spans.push_back(span_of(values, value, faces));
  return spans;
}

// The sharp corners the mode makes at the base level (see face_varying.h; OpenSubdiv's
// FVarLevel::completeTopologyFromFaceValues and gatherValueSpans). Values whose span is
// disjoint or cut by an infinitely sharp edge are corners through the value mesh's own
// tags; so are semi-sharp ones while their edges are sharp.
void tag_base_corners(const Level& vertices, Level& values, FaceVaryingLinear mode, BoundaryInterpolation boundary) {
  const std::vector<std::uint8_t> seam = seam_vertices(vertices, values);
  const bool corners_sharp = mode != FaceVaryingLinear::None;
  const bool plus = mode == FaceVaryingLinear::CornersPlus1 || mode == FaceVaryingLinear::CornersPlus2;
  const bool plus2 = mode == FaceVaryingLinear::CornersPlus2;
  const bool vertex_corners_smooth = boundary != BoundaryInterpolation::EdgesAndCorners;
  auto sharpen = [&](Index value, float sharpness = kInfinitelySharp) {
    values.vertex_sharpness[value] = std::max(values.vertex_sharpness[value], sharpness);
  };
  for (Index v = 0; v < vertices.vertex_count; ++v) {
    const std::vector<Span> spans = spans_at(vertices, values, v);
    if (spans.empty()) continue;
    const bool boundary_vertex = vertices.on_boundary(v);
    if (!seam[v]) {
      // Matching values follow the vertex, except a corner the vertex rule leaves smooth.
      if (boundary_vertex && spans.size() == 1 && spans[0].faces == 1 && vertex_corners_smooth && corners_sharp)
        sharpen(spans[0].value);
      continue;
    }
    bool all = vertices.non_manifold_vertex(v) || (plus && spans.size() > 2) ||
               (plus2 && spans.size() == 1 && !boundary_vertex);
    if (plus && spans.size() == 2) {
      all = all || spans[0].disjoint || spans[1].disjoint || (plus2 && (spans[0].faces == 1 || spans[1].faces == 1));
      // Dependent sharpness: where one of two values is semi-sharp, the other is sharp as long
      // as it (OpenSubdiv's depSharp; its sharpness stands in for the span's edges).
      for (int k = 0; k < 2 && !all; ++k)
        if (spans[k].semi_sharp > 0 && spans[1 - k].semi_sharp == 0) sharpen(spans[1 - k].value, spans[k].semi_sharp);
    }
    for (const Span& s : spans)
      if (all || (s.faces == 1 && corners_sharp)) sharpen(s.value);
  }
}

// Modes that stay linear at every level: Boundaries (every value on the value mesh's
// boundary), All (every value and edge).
void tag_linear(Level& values, FaceVaryingLinear mode) {
  if (mode != FaceVaryingLinear::Boundaries && mode != FaceVaryingLinear::All) return;
  values.vertex_sharpness.resize(size_t(values.vertex_count), 0.f);
  values.edge_sharpness.resize(size_t(values.edge_count()), 0.f);
  for (Index u = 0; u < values.vertex_count; ++u)
    if (mode == FaceVaryingLinear::All || values.on_boundary(u)) values.vertex_sharpness[u] = kInfinitelySharp;
  if (mode == FaceVaryingLinear::All) std::fill(values.edge_sharpness.begin(), values.edge_sharpness.end(), kInfinitelySharp);
}

// A split whose new faces each lie in one old face refines the islands one by one: that
// must give the mesh's own faces, in the same order (a split whose faces depend on where
// the boundaries are may not; crossing_step.h handles the built-in ones that differ).
void check_split(const Scheme& scheme, const Level& vertex_child, const Level& value_child) {
  bool same = vertex_child.face_count() == value_child.face_count();
  for (Index f = 0; same && f < vertex_child.face_count(); ++f) same = vertex_child.face_size(f) == value_child.face_size(f);
  if (!same)
    throw Error(fmt::format("{}: scheme {} uses the {} split, which splits the UV islands (seams as boundaries) "
                            "into other faces than the mesh, so face-varying data (e.g. UVs with seams) cannot follow "
                            "it. Drop the face-varying data or choose a scheme with another split", scheme.path,
                            subdiv::quoted(scheme.name), subdiv::quoted(splitter_info(scheme.split()).name)));
}

// Dual splits make every new point from a face corner (OriginKind::Corner).
bool makes_corner_points_only(const ChildOrigins& o) {
  return !o.kind.empty() &&
         std::all_of(o.kind.begin(), o.kind.end(), [](OriginKind k) { return k == OriginKind::Corner; });
}

// A dual step: every new point is a face corner, and its value is the dual rule applied to
// that corner in its own island (the value mesh, whose corner points are the same face
// corners). Each point then has one value: the data has no seams after the step, and the
// faces a dual split makes across a seam (E-faces) or around a seam vertex (V-faces) join
// values of two islands. `vertex_of` becomes the new values' vertices.
FaceVaryingLevel dual_step_values(const Level& parent, const ChildOrigins& vertex_origins, const Level& child,
                                  const ChildOrigins& value_origins, std::vector<double> values,
                                  std::vector<Index>& vertex_of) {
  std::vector<Index> value_at_corner(parent.face_vertices.size(), kNone);
  for (size_t c = 0; c < value_origins.kind.size(); ++c)
    value_at_corner[size_t(parent.face_offsets[value_origins.parent[c]]) + value_origins.local[c]] = Index(c);
  std::vector<Index> value_of_vertex(size_t(child.vertex_count));
  vertex_of.assign(value_origins.kind.size(), kNone);
  for (Index v = 0; v < child.vertex_count; ++v) {
    value_of_vertex[v] = value_at_corner[size_t(parent.face_offsets[vertex_origins.parent[v]]) + vertex_origins.local[v]];
    // A dual split with creases or corners (refine/dual_crease_topology.h) may join corner
    // points differently in the value mesh, where seams are boundaries.
    if (value_of_vertex[v] == kNone)
      throw Error("face-varying data through a dual split where a seam meets a crease or corner is not supported; "
                  "refine the face-varying data with a primal scheme, or without sharp tags at the seam");
    vertex_of[value_of_vertex[v]] = v;
  }
  FaceVaryingLevel out{std::move(values), {}};
  for (Index v : child.face_vertices) out.indices.push_back(value_of_vertex[v]);
  return out;
}

// Values that stay old values (a vertex's new point in its face's island) keep the sharp
// corner tags the mode gave them, as the primal splits' children do (framework/refine).
void inherit_corner_tags(const std::vector<float>& parent_tags, const std::vector<Index>& moved_value, Level& values) {
  if (parent_tags.empty()) return;
  values.vertex_sharpness.resize(size_t(values.vertex_count), 0.f);
  for (size_t u = 0; u < moved_value.size(); ++u)
    if (moved_value[u] != kNone) {
      const float inherited = decremented_sharpness(parent_tags[moved_value[u]]);
      values.vertex_sharpness[u] = std::max(values.vertex_sharpness[u], inherited);
    }
}

// Per-vertex scheme parameters on the values: each value takes its vertex's.
VertexParameters parameters_on_values(const VertexParameters& on_vertices, const std::vector<Index>& vertex_of) {
  VertexParameters out;
  for (const auto& [name, per_vertex] : on_vertices) {
    std::vector<double>& values = out[name];
    for (Index v : vertex_of) values.push_back(per_vertex[v]);
  }
  return out;
}

}  // namespace

const char* face_varying_linear_name(FaceVaryingLinear mode) {
  switch (mode) {
    case FaceVaryingLinear::None: return "none";
    case FaceVaryingLinear::CornersOnly: return "corners-only";
    case FaceVaryingLinear::CornersPlus1: return "corners-plus1";
    case FaceVaryingLinear::CornersPlus2: return "corners-plus2";
    case FaceVaryingLinear::Boundaries: return "boundaries";
    case FaceVaryingLinear::All: return "all";
  }
  return "";
}

FaceVaryingLinear face_varying_linear_from_tag(int value) {
  if (value < 0 || value > 5)
    throw Error(fmt::format("face-varying interpolation {} is not one of OpenSubdiv's 0..5 (none, corners-only, "
                            "corners-plus1, corners-plus2, boundaries, all)", value));
  return FaceVaryingLinear(value);
}

FaceVaryingValueMesh face_varying_value_mesh(const Level& vertices, const FaceVaryingLevel& base, int components,
                                             FaceVaryingLinear mode, BoundaryInterpolation boundary) {
  if (components < 1) throw Error("face-varying data needs at least one component per value");
  Renumbered start = renumber(vertices, base, components);
  FaceVaryingValueMesh out;
  out.level = value_mesh(vertices, start.level.indices, Index(start.vertex_of.size()));
  copy_sharpness(vertices, out.level);
  tag_base_corners(vertices, out.level, mode, boundary);
  tag_linear(out.level, mode);
  out.values = std::move(start.level);
  out.vertex_of = std::move(start.vertex_of);
  return out;
}

std::vector<FaceVaryingLevel> refine_face_varying(std::span<const SchemeRun> runs, const Hierarchy& h,
                                                  const FaceVaryingLevel& base, int components,
                                                  FaceVaryingLinear mode, const RefineOptions& options) {
  if (components < 1) throw Error("face-varying data needs at least one component per value");
  Renumbered start = renumber(h.levels[0], base, components);
  std::vector<FaceVaryingLevel> out{start.level};
  std::vector<Index> vertex_of = std::move(start.vertex_of);
  Level current = value_mesh(h.levels[0], start.level.indices, Index(vertex_of.size()));
  copy_sharpness(h.levels[0], current);
  tag_base_corners(h.levels[0], current, mode, options.features.boundary);
  std::vector<const Scheme*> per_level;
  for (const SchemeRun& run : runs) per_level.insert(per_level.end(), size_t(run.levels), run.scheme);
  VertexParameters parameters = options.vertex_parameters;
  for (size_t l = 0; l + 1 < h.levels.size() && l < per_level.size(); ++l) {
    if (l > 0) parameters = carry_vertex_parameters(h.levels[l - 1], h.origins[l - 1], parameters);
    tag_linear(current, mode);
    const SchemeRun run{per_level[l], 1};
    RefineOptions step = options;
    step.first_step = options.first_step + int(l);
    step.features.boundary = BoundaryInterpolation::EdgesOnly;  // corners were tagged above
    step.vertex_parameters = parameters_on_values(parameters, vertex_of);
    const Level& parent = h.levels[l];
    const Level& child = h.levels[l + 1];
    if (!makes_corner_points_only(h.origins[l]) && !corners_in_parent_faces(parent, h.origins[l], child)) {
      // New faces across old edges (crossing_step.h): the data follows the vertex split.
      const std::vector<float> corner_tags = current.vertex_sharpness;
      CrossingStep next = crossing_step(run, parent, std::move(current), h.origins[l], child, h.features_refined[l],
                                        out.back().values, components, step);
      current = std::move(next.values);
      copy_sharpness(child, current);
      inherit_corner_tags(corner_tags, next.value_of_vertex_origin, current);
      vertex_of = std::move(next.vertex_of);
      out.push_back(std::move(next.level));
      continue;
    }
    const Hierarchy values = refine_topology(std::span(&run, 1), current, step);
    std::vector<double> refined = step_values(std::span(&run, 1), values, 0, out.back().values, components, step);
    if (makes_corner_points_only(h.origins[l])) {
      out.push_back(dual_step_values(parent, h.origins[l], child, values.origins[0], std::move(refined), vertex_of));
      current = value_mesh(child, out.back().indices, Index(vertex_of.size()));
      copy_sharpness(child, current);
      continue;
    }
    check_split(*per_level[l], child, values.levels[1]);
    FaceVaryingLevel next{std::move(refined), {values.levels[1].face_vertices.begin(), values.levels[1].face_vertices.end()}};
    // Each child value's vertex, from the corners the two children share.
    vertex_of.assign(size_t(values.levels[1].vertex_count), kNone);
    for (size_t c = 0; c < next.indices.size(); ++c) vertex_of[next.indices[c]] = child.face_vertices[c];
    current = values.levels[1];
    out.push_back(std::move(next));
  }
  return out;
}

}  // namespace subdiv
