#include "framework/limit/adaptive_refine.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/engine/ghost_rings.h"
#include "framework/features/base_tags.h"
#include "framework/limit/adaptive_face_varying.h"
#include "framework/limit/adaptive_progress.h"
#include "framework/limit/adaptive_stage.h"
#include "framework/limit/adaptive_transitions.h"
#include "framework/limit/cut_weight_tables.h"
#include "framework/limit/limit_surface.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/byte_size_text.h"
#include "framework/util/error.h"
#include "framework/util/memory_limit.h"
#include "framework/util/parallel_for_all.h"
#include "framework/util/quoted_text.h"
#include "framework/util/step_progress.h"

namespace subdiv {
namespace {

using Uv = std::array<double, 2>;

// What a regular patch may not contain: a vertex whose faces are not the regular number
// (inside: 4 quads or 6 triangles; on a boundary: 2 or 3, or a boundary corner of 1 or 2
// when corners are sharp), a non-manifold vertex, a crease through it, a sharp vertex, a hole.
bool feature_vertex(const Level& L, Index v, bool triangles, const FeatureOptions& features) {
  if (L.non_manifold_vertex(v) || L.vertex_sharp(v) > 0) return true;
  for (Index e : L.ring_edges(v))
    if (L.edge_sharp(e) > 0 && !L.edge_on_boundary(e)) return true;
  for (Index f : L.ring_faces(v))
    if (L.is_hole(f)) return true;
  const int faces = L.incident_face_count(v);
  if (!L.on_boundary(v)) return faces != (triangles ? 6 : 4);
  if (faces == (triangles ? 3 : 2)) return false;
  return !(faces == (triangles ? 2 : 1) && features.boundary == BoundaryInterpolation::EdgesAndCorners);
}

bool feature_face(const Level& L, Index f, bool triangles, const FeatureOptions& features) {
  if (L.face_size(f) != (triangles ? 3 : 4)) return true;
  for (Index v : L.face(f))
    if (feature_vertex(L, v, triangles, features)) return true;
  return false;
}

// The largest distance between the face's bilinear (linear) patch through its corners'
// limit points and the limit surface, at the points (i/4, j/4) of the face.
double deviation(const LimitSurface& surface, std::span<const double> base_points, Index base_face,
                 std::span<const Uv> corners, bool triangles) {
  constexpr int kSteps = 4;
  auto limit_at = [&](const Uv& uv) {
    return surface.evaluate(base_face, uv[0], uv[1], base_points, 3, 0).position;
  };
  std::vector<std::vector<double>> p;
  for (const Uv& c : corners) p.push_back(limit_at(c));
  double worst = 0;
  for (int i = 0; i <= kSteps; ++i)
    for (int j = 0; j <= kSteps; ++j) {
      if (triangles && i + j > kSteps) continue;
      const double s = double(i) / kSteps, t = double(j) / kSteps;
      // Weights of the corners: bilinear on a quad, barycentric on a triangle.
      std::vector<double> w = triangles ? std::vector<double>{1 - s - t, s, t}
                                        : std::vector<double>{(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
      Uv uv{0, 0};
      double x[3] = {0, 0, 0};
      for (size_t k = 0; k < w.size(); ++k) {
        uv[0] += w[k] * corners[k][0], uv[1] += w[k] * corners[k][1];
        for (int d = 0; d < 3; ++d) x[d] += w[k] * p[k][size_t(d)];
      }
      const std::vector<double> q = limit_at(uv);
      worst = std::max(worst, std::hypot(q[0] - x[0], q[1] - x[1], q[2] - x[2]));
    }
  return worst;
}

// Marks the stage's faces to split: candidates that touch a feature or are out of tolerance.
void choose_splits(AdaptiveStage& s, bool triangles, const AdaptiveOptions& o, std::span<const double> base_points) {
  const Level& L = s.level;
  s.split.assign(size_t(L.face_count()), 0);
  parallel_for_all(size_t(L.face_count()), [&](size_t f) {
    if (!s.candidate[f] || L.is_hole(Index(f))) return;
    if (feature_face(L, Index(f), triangles, o.features)) {
      s.split[f] = 1;
      return;
    }
    if (o.tolerance > 0) {
      const Uv* c = s.corner_uv.data() + L.face_offsets[f];
      s.split[f] = deviation(*o.surface, base_points, s.base_face[f], {c, size_t(L.face_size(Index(f)))}, triangles) >
                   o.tolerance;
    }
  }, LoopProgress::Told);
}

// Writes the output faces: every face not split, with the finer vertices along its edges,
// and per face-varying channel each corner's value vertex (of the face's own side).
struct Stitcher {
  std::vector<AdaptiveStage>& stages;
  const std::vector<std::vector<AdaptiveValueStage>>& channels;  // per channel: its stages
  int levels;
  AdaptiveMesh& out;
  std::vector<std::pair<int, Index>> corner_vertex;  // per output corner: (stage, vertex)
  std::vector<std::vector<Index>> corner_value;      // per channel, per output corner: value

  // Edge (a, b) of stage l when a face beside it is split there, else kNone.
  Index split_edge(int l, Index a, Index b) const {
    if (l >= levels) return kNone;
    const Level& L = stages[size_t(l)].level;
    const Index e = find_edge(L, a, b);
    for (Index f : L.faces_of_edge(e))
      if (stages[size_t(l)].split[size_t(f)]) return e;
    return kNone;
  }

  // A value vertex's child, or the child of value edge (a, b): the face beside a split face is
  // refined too (its rings), so the child is there.
  static Index value_child(const AdaptiveValueStage& s, Index a, Index b = kNone) {
    Index c = kNone;
    if (b == kNone) c = s.vertex_child[size_t(a)];
    else if (const Index e = find_edge(s.level, a, b); e != kNone) c = s.edge_child[size_t(e)];
    if (c == kNone) throw Error("adaptive refinement: a face-varying value along a split edge was not computed");
    return c;
  }

  // The vertices along edge (a, b) of stage l from a up to b (b excluded), at the finest
  // stage either side of the edge was split to; (u, v) between those of a and b; per channel
  // the values va, vb of the face's side at a and b.
  void chain(int l, Index a, Index b, const Uv& ua, const Uv& ub, bool corner, const std::vector<Index>& va,
             const std::vector<Index>& vb) {
    if (const Index e = split_edge(l, a, b); e != kNone) {
      const AdaptiveStage& s = stages[size_t(l)];
      const Index m = s.edge_child[size_t(e)];
      const Uv um{0.5 * (ua[0] + ub[0]), 0.5 * (ua[1] + ub[1])};
      std::vector<Index> ca(va.size()), cm(va.size()), cb(va.size());
      for (size_t k = 0; k < va.size(); ++k) {
        const AdaptiveValueStage& t = channels[k][size_t(l)];
        ca[k] = value_child(t, va[k]), cm[k] = value_child(t, va[k], vb[k]), cb[k] = value_child(t, vb[k]);
      }
      chain(l + 1, s.vertex_child[size_t(a)], m, ua, um, corner, ca, cm);
      chain(l + 1, m, s.vertex_child[size_t(b)], um, ub, false, cm, cb);
      return;
    }
    corner_vertex.emplace_back(l, a);
    for (size_t k = 0; k < va.size(); ++k) corner_value[k].push_back(va[k]);
    out.corner_uv.push_back(ua);
    out.corner_is_face_corner.push_back(corner ? 1 : 0);
  }

  void emit(int l, Index f) {
    const AdaptiveStage& s = stages[size_t(l)];
    if (l < levels && s.split[size_t(f)]) {
      for (Index c : s.children[size_t(f)]) emit(l + 1, c);
      return;
    }
    const auto fv = s.level.face(f);
    const size_t first = size_t(s.level.face_offsets[size_t(f)]);
    std::vector<Index> va(channels.size()), vb(channels.size());
    for (size_t k = 0; k < fv.size(); ++k) {
      const size_t k1 = (k + 1) % fv.size();
      for (size_t c = 0; c < channels.size(); ++c) {
        const auto values = channels[c][size_t(l)].level.face(f);
        va[c] = values[k], vb[c] = values[k1];
      }
      chain(l, fv[k], fv[k1], s.corner_uv[first + k], s.corner_uv[first + k1], true, va, vb);
    }
    out.face_offsets.push_back(Index(corner_vertex.size()));
    out.face_level.push_back(l);
    out.base_face.push_back(s.base_face[size_t(f)]);
  }
};

// Output vertex numbers: a vertex is the same point at every stage that has it, numbered at
// the finest; its position is that stage's point.
void number_vertices(std::vector<AdaptiveStage>& stages, Stitcher& st, AdaptiveMesh& out) {
  std::vector<std::vector<Index>> number(stages.size());
  for (size_t l = 0; l < stages.size(); ++l) number[l].assign(size_t(stages[l].level.vertex_count), kNone);
  for (const auto& [l0, v0] : st.corner_vertex) {
    int l = l0;
    Index v = v0;
    while (size_t(l) + 1 < stages.size() && !stages[size_t(l)].vertex_child.empty() &&
           stages[size_t(l)].vertex_child[size_t(v)] != kNone)
      v = stages[size_t(l)].vertex_child[size_t(v)], ++l;
    Index& n = number[size_t(l)][size_t(v)];
    if (n == kNone) {
      n = Index(out.positions.size() / 3);
      const auto& p = stages[size_t(l)].points;
      const int C = stages[size_t(l)].channels;
      const auto at = p.begin() + std::ptrdiff_t(C) * v;
      out.positions.insert(out.positions.end(), at, at + 3);
      out.data.insert(out.data.end(), at + 3, at + C);
    }
    out.face_vertices.push_back(n);
  }
}

// Each channel's values numbered as the vertices are: a value at the finest stage that has it.
void number_values(const std::vector<std::vector<AdaptiveValueStage>>& channels, std::span<const AdaptiveValueMesh> in,
                   const Stitcher& st, AdaptiveMesh& out) {
  for (size_t k = 0; k < channels.size(); ++k) {
    const std::vector<AdaptiveValueStage>& stages = channels[k];
    const size_t C = size_t(in[k].components);
    AdaptiveFaceVarying& a = out.face_varying.emplace_back();
    a.components = int(C);
    std::vector<std::vector<Index>> number(stages.size());
    for (size_t l = 0; l < stages.size(); ++l) number[l].assign(size_t(stages[l].level.vertex_count), kNone);
    for (size_t c = 0; c < st.corner_vertex.size(); ++c) {
      size_t l = size_t(st.corner_vertex[c].first);
      Index u = st.corner_value[k][c];
      while (l + 1 < stages.size() && !stages[l].vertex_child.empty() && stages[l].vertex_child[size_t(u)] != kNone)
        u = stages[l].vertex_child[size_t(u)], ++l;
      Index& n = number[l][size_t(u)];
      if (n == kNone) {
        n = Index(a.value_level.size());
        a.value_level.push_back(int(l));
        const auto at = stages[l].values.begin() + std::ptrdiff_t(C) * u;
        a.values.insert(a.values.end(), at, at + std::ptrdiff_t(C));
      }
      a.indices.push_back(n);
    }
  }
}

// Every vertex moved to the limit surface, evaluated at one of its corners' (face, u, v).
void move_to_limit(AdaptiveMesh& out, const LimitSurface& surface, std::span<const double> base_points, int channels) {
  const size_t count = out.positions.size() / 3;
  std::vector<size_t> face_of(count, SIZE_MAX), corner_of(count, SIZE_MAX);
  for (size_t f = 0; f + 1 < out.face_offsets.size(); ++f)
    for (Index k = out.face_offsets[f]; k < out.face_offsets[f + 1]; ++k)
      if (const size_t v = size_t(out.face_vertices[size_t(k)]); corner_of[v] == SIZE_MAX)
        face_of[v] = f, corner_of[v] = size_t(k);
  tbb::enumerable_thread_specific<LimitSample> samples;  // one per thread, its memory reused
  parallel_for_all(count, [&](size_t v) {
    const Uv& uv = out.corner_uv[corner_of[v]];
    LimitSample& s = samples.local();
    surface.evaluate_into(out.base_face[face_of[v]], uv[0], uv[1], base_points, channels, 0, s);
    const std::vector<double>& p = s.position;
    std::copy(p.begin(), p.begin() + 3, out.positions.begin() + std::ptrdiff_t(3 * v));
    const size_t D = size_t(channels - 3);
    std::copy(p.begin() + 3, p.end(), out.data.begin() + std::ptrdiff_t(D * v));
  }, LoopProgress::Told);
}

// About what the stages and the output hold per face of the finest stage: 0.79 kB per face
// measured for a uniform level 7 of a 48-quad torus (--tolerance 1e-300), written mesh included.
constexpr double kBytesPerStageFace = 800;

// Refuses a stage that would not fit before building it: a tolerance near 0 asks for the
// uniform level, four times larger each level, where the process would otherwise run out
// of memory (or be killed) half-way.
// Stages of fewer faces are chosen and refined on the calling thread alone.
constexpr Index kSerialFaces = 4096;

// Each face-varying channel refines a stage of its own over the same faces (`stages`).
void check_stage_fits(double split_count, int level, size_t stages, const char* fix) {
  const double need = 4.0 * split_count * kBytesPerStageFace * double(stages);
  if (need < kUncheckedBytes) return;
  const MemoryBudget have = available_memory();
  if (need > have.bytes) {
    const auto [need_text, have_text] = byte_sizes_compared(need, have.bytes);
    throw Error(fmt::format("adaptive refinement: level {} would split {:.0f} faces into about {:.0f} and need about {}, "
                            "but only {} of memory is available (limited by {}); {}",
                            level, split_count, 4 * split_count, need_text, have_text, have.source, fix));
  }
}

// In double: level 12 of a large mesh has more faces than an Index counts.
double uniform_faces(const Level& base, bool triangles, int levels) {
  double faces = 0;  // holes make none
  for (Index f = 0; f < base.face_count(); ++f)
    if (!base.is_hole(f)) faces += triangles || levels == 0 ? 1.0 : double(base.face_size(f));
  for (int l = triangles ? 0 : 1; l < levels; ++l) faces *= 4;
  return faces;
}

// A non-manifold mesh is refined on its own levels, as uniform refinement refines it: its
// non-manifold edges are infinitely sharp and its non-manifold vertices corners (or creases)
// by the base tags every stage's refinement gives its piece (features/base_tags.h), and they
// are features, so every face around them is split at every level and each stage holds them
// with all their faces. A face that repeats a vertex is refused: its corners' (u, v) would
// be ambiguous, and the limit evaluation cannot follow it either.
void check_no_repeated_corner(const Level& base) {
  if (base.manifold()) return;
  for (Index f = 0; f < base.face_count(); ++f) {
    const auto fv = base.face(f);
    for (size_t i = 0; i < fv.size(); ++i)
      for (size_t j = 0; j < i; ++j) {
        if (fv[i] != fv[j]) continue;
        const bool side = i == j + 1 || (j == 0 && i + 1 == fv.size());
        const std::string edge = side ? fmt::format(" (its edge {0}-{0} joins the vertex to itself)", fv[i]) : "";
        throw Error(fmt::format("adaptive refinement needs faces with distinct corners, but face {} repeats vertex {}{} "
                                "(faces and vertices counted from 0); remove the repeat from the face, or refine "
                                "the mesh uniformly",
                                f, fv[i], edge));
      }
  }
}

}  // namespace

// Pieces have the base's valences and, along their cuts and boundaries, 1 to the regular one:
// the first table is made for all of them.
AdaptiveTables::AdaptiveTables(const Scheme& scheme)
    : scheme_(&scheme), cache_(cut_weight_tables(scheme, !scheme_is_level_dependent(scheme))) {}

AdaptiveTables::~AdaptiveTables() = default;

AdaptiveMesh refine_adaptive(const Scheme& scheme, const Level& input, std::span<const double> positions,
                             const AdaptiveOptions& options, std::span<const double> data, int data_channels) {
  // With boundary interpolation "none" the faces along a boundary are holes, as uniform
  // refinement (engine/refiner.cpp) and OpenSubdiv make them: no refined faces, no limit.
  std::optional<Level> with_boundary_holes;
  if (options.features.boundary == BoundaryInterpolation::None)
    tag_boundary_holes(with_boundary_holes.emplace(input), options.features.boundary);
  const Level& base = with_boundary_holes ? *with_boundary_holes : input;
  const SplitKind split = scheme.split();
  if (split != SplitKind::Quad && split != SplitKind::Triangle)
    throw Error(fmt::format("scheme {}: adaptive refinement is implemented for the binary quad and triangle splits "
                            "only so far; refine it uniformly instead (`subdiv refine MESH -s {} -l {}`, with "
                            "`--limit` for the finest level on the limit surface; Python: `subdivkit.refine`)",
                            subdiv::quoted(scheme.name), scheme_argument(scheme), options.levels));
  const int levels = options.levels;
  if (levels < 0 || levels > 12) throw Error(fmt::format("adaptive refinement to level {}: give 0 to 12", levels));
  if ((options.limit || options.tolerance > 0) && !options.surface)
    throw Error("adaptive refinement: limit positions and a tolerance need the limit surface's evaluator");
  check_no_repeated_corner(base);
  const bool triangles = split == SplitKind::Triangle;
  const SchemeRun run{&scheme, 1};
  const int ghosts = ghost_rings({&run, 1});
  const int rings = std::max(ghosts, 1);

  if (data_channels < 0 || data.size() != size_t(base.vertex_count) * size_t(data_channels))
    throw Error(fmt::format("adaptive refinement: {} point-array values given for {} vertices and {} channels",
                            data.size(), base.vertex_count, data_channels));
  // The positions and the point arrays side by side: one product per stage carries both.
  const int C = 3 + data_channels;
  std::vector<double> points(size_t(base.vertex_count) * size_t(C));
  for (Index v = 0; v < base.vertex_count; ++v) {
    std::copy_n(positions.begin() + 3 * v, 3, points.begin() + std::ptrdiff_t(C) * v);
    std::copy_n(data.begin() + std::ptrdiff_t(data_channels) * v, data_channels,
                points.begin() + std::ptrdiff_t(C) * v + 3);
  }
  std::vector<AdaptiveStage> stages;
  stages.push_back(base_stage(base, points, C, triangles));
  std::vector<std::vector<AdaptiveValueStage>> channels;  // per face-varying channel: its stages
  for (const AdaptiveValueMesh& channel : options.face_varying) channels.push_back({value_base_stage(base, channel)});
  AdaptiveMesh out;
  out.data_channels = data_channels;
  // A front-end's bar (util/step_progress.h): per level, choosing the faces and refining
  // them, each level's share sized by its faces; then the limit positions. Without a
  // tolerance only the faces near features split, a band that about doubles per level.
  AdaptiveProgress progress(levels, options.limit, options.tolerance > 0 || options.uniform ? 4.0 : 2.0);
  std::optional<AdaptiveTables> own_tables;
  if (options.tables && &options.tables->scheme() != &scheme)
    throw Error(fmt::format("adaptive refinement with scheme {}: the weight tables kept are scheme {}'s",
                            subdiv::quoted(scheme.name), subdiv::quoted(options.tables->scheme().name)));
  AdaptiveTables& tables = options.tables ? *options.tables : own_tables.emplace(scheme);
  if (options.uniform && levels > 0)
    check_stage_fits(uniform_faces(base, triangles, levels - 1), levels, 1 + channels.size(), "ask for a lower level");
  tbb::task_arena serial(1);
  for (int l = 0; l < levels; ++l) {
    AdaptiveStage& s = stages.back();
    // A small level runs on this thread alone: its loops are shorter than handing them out.
    const bool small = s.level.face_count() < kSerialFaces;
    const auto [level_begin, level_end] = progress.level_span(l, double(s.level.face_count()));
    const double level_middle = (level_begin + level_end) / 2;
    {
      const StepProgressScope::Report share = StepProgressScope::span(level_begin, level_middle);
      const StepProgressScope choosing(share);
      if (small && options.tolerance == 0) serial.execute([&] { choose_splits(s, triangles, options, positions); });
      else choose_splits(s, triangles, options, positions);
    }
    const Index split_count = Index(std::count(s.split.begin(), s.split.end(), 1));
    out.split_faces.push_back(split_count);
    if (split_count == 0) break;
    check_stage_fits(double(split_count), l + 1, 1 + channels.size(), "ask for fewer levels or a larger tolerance");
    RefineOptions ro;
    ro.levels = 1;
    ro.features = options.features;
    ro.first_step = options.first_step + l;
    ro.evaluation.weight_tables = &tables.cache();
    const StepProgressScope::Report share = StepProgressScope::span(level_middle, level_end);
    const StepProgressScope refining(share);
    // The last stage is only read for its faces and corners (the stitcher splits none of it).
    const bool last = l + 1 == levels;
    AdaptiveStage next = small ? serial.execute([&] { return refine_stage(scheme, s, rings, ghosts, ro, triangles, last); })
                               : refine_stage(scheme, s, rings, ghosts, ro, triangles, last);
    for (size_t k = 0; k < channels.size(); ++k) {
      auto refine_values = [&] {
        return refine_value_stage(scheme, s, next, channels[k].back(), options.face_varying[k], ghosts, ro, last);
      };
      channels[k].push_back(small ? serial.execute(refine_values) : refine_values());
    }
    out.computed_faces.push_back(next.level.face_count());
    stages.push_back(std::move(next));
  }
  const int reached = int(stages.size()) - 1;
  Stitcher st{stages, channels, reached, out, {}, std::vector<std::vector<Index>>(channels.size())};
  for (Index f = 0; f < base.face_count(); ++f)
    if (!base.is_hole(f)) st.emit(0, f);
  number_vertices(stages, st, out);
  number_values(channels, options.face_varying, st, out);
  if (options.limit) {
    const auto [limit_begin, limit_end] = progress.limit_span();
    const StepProgressScope::Report share = StepProgressScope::span(limit_begin, limit_end);
    const StepProgressScope moving(share);
    move_to_limit(out, *options.surface, points, C);
  }
  // After the limit: each vertex is evaluated at the corner the polygons list first.
  if (options.transitions == AdaptiveTransitions::Triangles) tessellate_transitions(out);
  out.uniform_faces = Index(std::min(uniform_faces(base, triangles, levels), double(std::numeric_limits<Index>::max())));
  return out;
}

}  // namespace subdiv
