#include "framework/primvar/level_data.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

bool interpolated(const DataArray& a) { return !a.integer; }

// Positions and every interpolated array, interleaved per vertex: x y z a0 a1 ... .
int packed_channels(const LevelData& level) {
  int channels = 3;
  for (const DataArray& a : level.point_data)
    if (interpolated(a)) channels += a.components;
  return channels;
}

std::vector<double> pack(const LevelData& level, Index vertices, int channels) {
  std::vector<double> packed(size_t(vertices) * size_t(channels));
  for (Index v = 0; v < vertices; ++v) {
    double* out = &packed[size_t(v) * channels];
    std::copy_n(&level.positions[3 * size_t(v)], 3, out);
    int at = 3;
    for (const DataArray& a : level.point_data) {
      if (!interpolated(a)) continue;
      std::copy_n(&a.values[size_t(v) * a.components], a.components, out + at);
      at += a.components;
    }
  }
  return packed;
}

void unpack(const std::vector<double>& packed, int channels, Index vertices, LevelData& out) {
  out.positions.resize(size_t(vertices) * 3);
  for (Index v = 0; v < vertices; ++v) std::copy_n(&packed[size_t(v) * channels], 3, &out.positions[3 * size_t(v)]);
  int at = 3;
  for (DataArray& a : out.point_data) {
    if (!interpolated(a)) continue;
    a.values.resize(size_t(vertices) * a.components);
    for (Index v = 0; v < vertices; ++v)
      std::copy_n(&packed[size_t(v) * channels + at], a.components, &a.values[size_t(v) * a.components]);
    at += a.components;
  }
}

// The value the vertices `vs` share, else the smallest (the shared value is the smallest).
double shared_or_smallest(std::span<const Index> vs, std::span<const double> values, int components, int c) {
  double smallest = std::numeric_limits<double>::infinity();
  for (Index v : vs) smallest = std::min(smallest, values[size_t(v) * components + c]);
  return smallest;
}

// The parent face a child face lies in or, failing that, that of its first corner point.
Index cell_parent(const Level& child, const ChildOrigins& o, Index f) {
  if (size_t(f) < o.parent_face.size() && o.parent_face[f] != kNone) return o.parent_face[f];
  for (Index c : child.face(f)) {
    const OriginKind kind = o.kind[c];
    if (kind == OriginKind::Corner || kind == OriginKind::Face) return o.parent[c];
  }
  return kNone;
}

}  // namespace

std::vector<DataArray> carried_point_arrays(const std::vector<DataArray>& arrays, std::vector<std::string>* dropped) {
  std::vector<DataArray> out;
  for (const DataArray& a : arrays) {
    if (a.role != ArrayRole::Normals) out.push_back(a);
    else if (dropped) dropped->push_back(a.name);
  }
  return out;
}

void check_finite_arrays(const LevelData& level, const std::string& source) {
  auto check = [&](const std::vector<DataArray>& arrays, const char* per) {
    for (const DataArray& a : arrays)
      for (size_t i = 0; i < a.values.size(); ++i)
        if (!std::isfinite(a.values[i]))
          throw Error(fmt::format("{}: {} array {} holds {} at {} {}; refinement would spread it to the neighbours: "
                                  "fill it in, or remove the array", source, per, subdiv::quoted(a.name), a.values[i], per,
                                  i / size_t(a.components)));
  };
  check(level.point_data, "point");
  check(level.cell_data, "cell");
}

std::vector<double> carry_integer_tuples(const Level& parent, const ChildOrigins& o, std::span<const double> values,
                                         int components) {
  std::vector<double> out(o.kind.size() * size_t(components));
  for (size_t child = 0; child < o.kind.size(); ++child) {
    const Index p = o.parent[child];
    for (int c = 0; c < components; ++c) {
      double& x = out[child * components + c];
      switch (o.kind[child]) {
        case OriginKind::Vertex: x = values[size_t(p) * components + c]; break;
        case OriginKind::Edge:
          x = shared_or_smallest(std::span(&parent.edge_vertices[2 * size_t(p)], 2), values, components, c);
          break;
        case OriginKind::Face: x = shared_or_smallest(parent.face(p), values, components, c); break;
        case OriginKind::Corner: x = values[size_t(parent.face(p)[o.local[child]]) * components + c]; break;
      }
    }
  }
  return out;
}

std::vector<double> inherit_cell_tuples(const Level&, const Level& child, const ChildOrigins& o,
                                        std::span<const double> values, int components, bool integer) {
  std::vector<double> out(size_t(child.face_count()) * components, integer ? -1.0 : std::nan(""));
  for (Index f = 0; f < child.face_count(); ++f)
    if (const Index p = cell_parent(child, o, f); p != kNone)
      std::copy_n(&values[size_t(p) * components], components, &out[size_t(f) * components]);
  return out;
}

LevelData next_level_data(std::span<const SchemeRun> runs, const Hierarchy& h, int step, const LevelData& level,
                          const RefineOptions& options) {
  const Level& parent = h.levels[step];
  const Level& child = h.levels[step + 1];
  const ChildOrigins& origins = h.origins[step];
  LevelData out;
  out.point_data = level.point_data;
  const int channels = packed_channels(level);
  if (channels == 3)  // positions alone: no copy into a packed buffer
    out.positions = step_values(runs, h, step, level.positions, 3, options);
  else
    unpack(step_values(runs, h, step, pack(level, parent.vertex_count, channels), channels, options), channels,
           child.vertex_count, out);
  for (DataArray& a : out.point_data)
    if (!interpolated(a)) a.values = carry_integer_tuples(parent, origins, a.values, a.components);
  for (const DataArray& a : level.cell_data) {
    DataArray c = a;
    c.values = inherit_cell_tuples(parent, child, origins, a.values, a.components, a.integer);
    out.cell_data.push_back(std::move(c));
  }
  return out;
}

}  // namespace subdiv
