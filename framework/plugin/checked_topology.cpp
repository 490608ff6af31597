#include "framework/plugin/checked_topology.h"

#include <cmath>
#include <cstddef>
#include <fmt/format.h>
#include <span>
#include <utility>

#include "framework/plugin/checked_rules.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// Offsets of a CSR array: `count` + 1 of them, from 0, never decreasing, ending at `total`.
std::string offsets_problem(std::span<const Index> offsets, std::size_t count, std::size_t total, const char* name) {
  if (offsets.size() != count + 1)
    return fmt::format("{} has {} entries, not {} (one more than the elements)", name, offsets.size(), count + 1);
  if (offsets[0] != 0) return fmt::format("{} starts at {}, not 0", name, offsets[0]);
  for (std::size_t i = 0; i < count; ++i)
    if (offsets[i + 1] < offsets[i]) return fmt::format("{} decreases at entry {}", name, i + 1);
  if (std::size_t(offsets[count]) != total)
    return fmt::format("{} ends at {}, but its array has {} entries", name, offsets[count], total);
  return {};
}

// Every entry of `values` in [low, end).
std::string range_problem(std::span<const Index> values, Index low, Index end, const char* name, const char* what) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (values[i] < low || values[i] >= end)
      return fmt::format("{}[{}] is {}, but the level has {} {} (0 to {})", name, i, values[i], end, what, end - 1);
  return {};
}

template <typename Vector>
std::string size_problem(const Vector& values, std::size_t size, bool may_be_empty, const char* name) {
  if (values.size() == size || (may_be_empty && values.empty())) return {};
  return fmt::format("{} has {} entries, not {}{}", name, values.size(), size, may_be_empty ? " (or none)" : "");
}

std::string faces_problem(const Level& c) {
  if (c.vertex_count < 0) return fmt::format("the child level has {} vertices", c.vertex_count);
  if (c.face_offsets.empty()) return "face_offsets is empty (it needs at least the leading 0)";
  const std::size_t F = c.face_offsets.size() - 1;
  if (auto p = offsets_problem(c.face_offsets, F, c.face_vertices.size(), "face_offsets"); !p.empty()) return p;
  for (std::size_t f = 0; f < F; ++f) {
    const Index size = c.face_offsets[f + 1] - c.face_offsets[f];
    if (size < 3 || size > kMaxFaceSize)
      return fmt::format("child face {} has {} corners; faces have 3 to {}", f, size, kMaxFaceSize);
  }
  return range_problem(c.face_vertices, 0, c.vertex_count, "face_vertices", "vertices");
}

Index element_count(const Level& parent, OriginKind kind) {
  switch (kind) {
    case OriginKind::Vertex:
      return parent.vertex_count;
    case OriginKind::Edge:
      return parent.edge_count();
    case OriginKind::Face:
      return parent.face_count();
    case OriginKind::Corner:
      return parent.corner_count();
  }
  return 0;
}

std::string runs_problem(const Level& parent, const ChildOrigins& o, Index vertex_count) {
  const ChildRuns& runs = *o.runs;
  long long covered = 0;
  for (int k = 0; k < 4; ++k) {
    if (runs.count[k] == 0) continue;
    const OriginKind kind = OriginKind(k);
    const Index first = runs.first[k], count = runs.count[k];
    if (count != element_count(parent, kind) || first < 0 || (long long)first + count > vertex_count)
      return fmt::format(
          "origins.runs gives kind {} the children {} to {}, but the parent has {} such elements and "
          "the child {} vertices",
          k, first, (long long)first + count - 1, element_count(parent, kind), vertex_count);
    for (Index i = 0; i < count; ++i) {
      const Index c = first + i;
      const Index element =
          kind == OriginKind::Corner ? parent.face_offsets[std::size_t(o.parent[c])] + o.local[c] : o.parent[c];
      if (o.kind[c] != kind || element != i)
        return fmt::format(
            "origins.runs says child vertex {} comes from element {} of kind {}, but its origin says "
            "otherwise",
            c, i, k);
    }
    covered += count;
  }
  if (covered != vertex_count)
    return fmt::format("origins.runs covers {} of the {} child vertices", covered, vertex_count);
  return {};
}

std::string origins_problem(const Level& parent, const SplitResult& r) {
  const ChildOrigins& o = r.origins;
  const Index V = r.child.vertex_count;
  for (auto p : {size_problem(o.kind, std::size_t(V), false, "origins.kind"),
                 size_problem(o.parent, std::size_t(V), false, "origins.parent"),
                 size_problem(o.local, std::size_t(V), false, "origins.local"),
                 size_problem(o.parent_face, std::size_t(r.child.face_count()), true, "origins.parent_face")})
    if (!p.empty()) return p;
  for (Index c = 0; c < V; ++c) {
    if (int(o.kind[c]) > int(OriginKind::Corner))
      return fmt::format("origins.kind[{}] is {}, not a kind (0 vertex, 1 edge, 2 face, 3 corner)", c, int(o.kind[c]));
    const Index count = o.kind[c] == OriginKind::Corner ? parent.face_count() : element_count(parent, o.kind[c]);
    if (o.parent[c] < 0 || o.parent[c] >= count)
      return fmt::format("origins.parent[{}] is {}, but the parent level has {} elements of its kind {}", c,
                         o.parent[c], count, int(o.kind[c]));
    if (o.kind[c] == OriginKind::Corner && o.local[c] >= parent.face_size(o.parent[c]))
      return fmt::format("origins.local[{}] is corner {} of parent face {}, which has {} corners", c, o.local[c],
                         o.parent[c], parent.face_size(o.parent[c]));
  }
  if (auto p = range_problem(o.parent_face, kNone, parent.face_count(), "origins.parent_face", "faces"); !p.empty())
    return p;
  return o.runs ? runs_problem(parent, o, V) : std::string();
}

std::string edges_problem(const Level& c) {
  const std::size_t F = std::size_t(c.face_count()), E = c.edge_vertices.size() / 2;
  if (c.edge_vertices.size() % 2) return "edge_vertices has an odd number of entries";
  for (auto p : {size_problem(c.face_edges, c.face_vertices.size(), false, "face_edges"),
                 size_problem(c.edge_faces, 2 * E, false, "edge_faces"),
                 range_problem(c.edge_vertices, 0, c.vertex_count, "edge_vertices", "vertices"),
                 range_problem(c.face_edges, 0, Index(E), "face_edges", "edges"),
                 range_problem(c.edge_faces, kNone, Index(F), "edge_faces", "faces")})
    if (!p.empty()) return p;
  for (std::size_t f = 0; f < F; ++f)
    for (Index i = c.face_offsets[f]; i < c.face_offsets[f + 1]; ++i) {
      const Index next = i + 1 == c.face_offsets[f + 1] ? c.face_offsets[f] : i + 1;
      const Index e = c.face_edges[std::size_t(i)], a = c.face_vertices[std::size_t(i)],
                  b = c.face_vertices[std::size_t(next)];
      const Index x = c.edge_vertices[2 * std::size_t(e)], y = c.edge_vertices[2 * std::size_t(e) + 1];
      if (!((x == a && y == b) || (x == b && y == a)))
        return fmt::format("face {} corner {} runs from vertex {} to {} along edge {}, which joins {} and {}", f,
                           i - c.face_offsets[f], a, b, e, x, y);
    }
  for (std::size_t e = 0; e < E; ++e)
    if (c.edge_faces[2 * e] == kNone) return fmt::format("edge {} has no face in edge_faces[{}]", e, 2 * e);
  return {};
}

std::string non_manifold_problem(const Level& c) {
  const std::size_t E = std::size_t(c.edge_count());
  for (auto p : {size_problem(c.edge_non_manifold, E, true, "edge_non_manifold"),
                 size_problem(c.vertex_non_manifold, std::size_t(c.vertex_count), true, "vertex_non_manifold"),
                 range_problem(c.edge_face_list, 0, c.face_count(), "edge_face_list", "faces")})
    if (!p.empty()) return p;
  if (!c.edge_face_offsets.empty())
    return offsets_problem(c.edge_face_offsets, E, c.edge_face_list.size(), "edge_face_offsets");
  return {};
}

std::string rings_problem(const Level& c) {
  const std::size_t V = std::size_t(c.vertex_count);
  for (auto p : {offsets_problem(c.vertex_ring_offsets, V, c.vertex_edges.size(), "vertex_ring_offsets"),
                 offsets_problem(c.vertex_face_offsets, V, c.vertex_faces.size(), "vertex_face_offsets"),
                 size_problem(c.vertex_face_corner, c.vertex_faces.size(), false, "vertex_face_corner"),
                 size_problem(c.vertex_on_boundary, V, false, "vertex_on_boundary"),
                 range_problem(c.vertex_edges, 0, c.edge_count(), "vertex_edges", "edges"),
                 range_problem(c.vertex_faces, 0, c.face_count(), "vertex_faces", "faces")})
    if (!p.empty()) return p;
  for (Index v = 0; v < Index(V); ++v) {
    for (Index e : c.ring_edges(v))
      if (c.edge_vertices[2 * std::size_t(e)] != v && c.edge_vertices[2 * std::size_t(e) + 1] != v)
        return fmt::format("vertex {}'s ring lists edge {}, which does not end at it", v, e);
    for (Index i = c.vertex_face_offsets[std::size_t(v)]; i < c.vertex_face_offsets[std::size_t(v) + 1]; ++i) {
      const Index f = c.vertex_faces[std::size_t(i)];
      const int corner = c.vertex_face_corner[std::size_t(i)];
      if (corner >= c.face_size(f) || c.face(f)[std::size_t(corner)] != v)
        return fmt::format("vertex {}'s ring lists face {} at corner {}, which is not the vertex", v, f, corner);
    }
    if (!c.non_manifold_vertex(v) && c.valence(v) != c.incident_face_count(v) + (c.on_boundary(v) ? 1 : 0))
      return fmt::format("vertex {} has {} ring edges and {} ring faces, which does not fit a{} vertex", v,
                         c.valence(v), c.incident_face_count(v), c.on_boundary(v) ? " boundary" : "n interior");
  }
  return {};
}

std::string tags_problem(const Level& c) {
  for (auto p : {size_problem(c.face_hole, std::size_t(c.face_count()), true, "face_hole"),
                 size_problem(c.edge_sharpness, std::size_t(c.edge_count()), true, "edge_sharpness"),
                 size_problem(c.vertex_sharpness, std::size_t(c.vertex_count), true, "vertex_sharpness")})
    if (!p.empty()) return p;
  for (const auto* tags : {&c.edge_sharpness, &c.vertex_sharpness})
    for (float s : *tags)
      if (std::isnan(s)) return "a sharpness is NaN";
  return {};
}

template <typename Fn>
std::function<SplitResult(const Level&, int)> guarded_split(Fn split, std::string who, bool faces_only,
                                                            bool propagates_tags) {
  return [split = std::move(split), who = std::move(who), faces_only, propagates_tags](const Level& parent, int step) {
    const char* what = faces_only ? "split_faces_only" : "split";
    SplitResult r = call_plugin(who, fmt::format("its {} function (step {})", what, step).c_str(),
                                [&] { return split(parent, step); });
    if (const std::string p = split_result_problem(parent, r, faces_only, propagates_tags); !p.empty())
      throw Error(
          fmt::format("{}: its {} function (step {}) returned a child level that cannot be used: {}; fix the "
                      "plugin",
                      who, what, step, p));
    return r;
  };
}

}  // namespace

std::string split_result_problem(const Level& parent, const SplitResult& r, bool faces_only, bool propagates_tags) {
  std::string p = faces_problem(r.child);
  if (p.empty()) p = origins_problem(parent, r);
  if (p.empty() && !faces_only) p = edges_problem(r.child);
  if (p.empty() && !faces_only) p = non_manifold_problem(r.child);
  if (p.empty() && !faces_only) p = rings_problem(r.child);
  if (p.empty()) p = tags_problem(r.child);
  if (p.empty() && propagates_tags && !faces_only &&
      (long long)r.child.vertex_count < (long long)parent.vertex_count + parent.edge_count())
    p = fmt::format(
        "the splitter says the engine may carry creases (engine_propagates_tags), which needs a child "
        "vertex per parent vertex and edge ({}), but the child has {} vertices",
        (long long)parent.vertex_count + parent.edge_count(), r.child.vertex_count);
  return p;
}

SplitterInfo checked_splitter(SplitterInfo info, const std::string& who) {
  const std::string label = fmt::format("{}, splitter {}", who, subdiv::quoted(info.name));
  if (!std::isfinite(info.scale) || info.scale <= 1.0 || info.period < 1 || info.feature_period < 1 ||
      !std::isfinite(info.topology_reach) || !std::isfinite(info.ring_scale) || info.ring_scale < 0)
    throw Error(
        fmt::format("{}: scale must be finite and above 1 (it is {}), period and feature_period 1 or more "
                    "(they are {} and {}), topology_reach and ring_scale finite (ring_scale 0 or more; they "
                    "are {} and {})",
                    label, info.scale, info.period, info.feature_period, info.topology_reach, info.ring_scale));
  if (info.split) info.split = guarded_split(std::move(info.split), label, false, info.engine_propagates_tags);
  if (info.split_faces_only)
    info.split_faces_only = guarded_split(std::move(info.split_faces_only), label, true, false);
  return info;
}

RoleInfo checked_role(RoleInfo info, const std::string& who) {
  const std::string label = fmt::format("{}, role {}", who, subdiv::quoted(info.name));
  if (auto points = std::move(info.points))
    info.points = [points, label](const Level& level, Index element, int corner, std::vector<Index>& out) {
      const std::size_t before = out.size();
      call_plugin(label, fmt::format("its points function (element {})", element).c_str(),
                  [&] { points(level, element, corner, out); });
      for (std::size_t i = before; i < out.size(); ++i)
        if (out[i] < 0 || out[i] >= level.vertex_count)
          throw Error(
              fmt::format("{}: its points function gives element {} the point {}, but the level has {} "
                          "vertices (0 to {}); fix the plugin",
                          label, element, out[i], level.vertex_count, level.vertex_count - 1));
    };
  if (auto max_points = std::move(info.max_points))
    info.max_points = [max_points, label](int n, int k) {
      const int m = call_plugin(label, fmt::format("its max_points function (n = {}, k = {})", n, k).c_str(),
                                [&] { return max_points(n, k); });
      if (m < 0 || m > kMaxRolePoints)
        throw Error(
            fmt::format("{}: its max_points function gives {} for valence {} and faces of {} sides; it must "
                        "be 0 to {}; fix the plugin",
                        label, m, n, k, kMaxRolePoints));
      return m;
    };
  return info;
}

}  // namespace subdiv
