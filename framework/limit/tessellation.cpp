#include "framework/limit/tessellation.h"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <initializer_list>
#include <map>
#include <tuple>
#include <tbb/enumerable_thread_specific.h>

#include "framework/limit/face_domain.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/limit/unit_normal.h"
#include "framework/util/byte_size_text.h"
#include "framework/util/memory_limit.h"
#include "framework/util/parallel_for_all.h"

namespace subdiv {
namespace {

// Where a grid point lies on the base mesh, so that faces sharing it share the point: a
// vertex, the m-th of N segment ends along an edge (from its first end), or a point of
// one face's own (its sub-face boundaries included).
using Key = std::tuple<int, Index, Index, Index>;  // kind, element, a, b
constexpr int kVertexKey = 0, kEdgeKey = 1, kFaceKey = 2;

struct Builder {
  const Level& base;
  Tessellation out;
  std::map<Key, Index> points;
  std::map<Index, Uv> here;  // the points of the face (or sub-face) being built: their (u, v) in it

  Index point(const Key& key, Index face, double u, double v) {
    auto [it, inserted] = points.emplace(key, out.point_count());
    if (inserted) {
      out.uv.insert(out.uv.end(), {u, v});
      out.uv_face.push_back(face);
    }
    here[it->second] = {u, v};
    return it->second;
  }
  void corners(std::initializer_list<Index> ids) {
    for (Index id : ids) {
      const Uv& uv = here.at(id);
      out.corner_uv.insert(out.corner_uv.end(), {uv[0], uv[1]});
    }
  }

  // The key of the point at fraction m / N along edge k of face f (from corner k).
  Key edge_key(Index f, int k, int m, int N) const {
    const auto corners = base.face(f);
    const int n = int(corners.size());
    if (m == 0) return {kVertexKey, corners[size_t(k)], 0, 0};
    if (m == N) return {kVertexKey, corners[size_t((k + 1) % n)], 0, 0};
    const Index e = base.face_edge_list(f)[size_t(k)];
    const bool forward = base.edge_vertices[size_t(2 * e)] == corners[size_t(k)];
    return {kEdgeKey, e, forward ? m : N - m, 0};
  }

  void quad(Index f, Index a, Index b, Index c, Index d) {
    out.face_vertices.insert(out.face_vertices.end(), {a, b, c, d});
    corners({a, b, c, d});
    out.face_offsets.push_back(Index(out.face_vertices.size()));
    out.base_face.push_back(f);
  }
  void triangle(Index f, Index a, Index b, Index c) {
    out.face_vertices.insert(out.face_vertices.end(), {a, b, c});
    corners({a, b, c});
    out.face_offsets.push_back(Index(out.face_vertices.size()));
    out.base_face.push_back(f);
  }

  void quad_face(Index f, int N) {
    here.clear();
    std::vector<Index> id(size_t((N + 1) * (N + 1)));
    for (int j = 0; j <= N; ++j)
      for (int i = 0; i <= N; ++i) {
        Key key{kFaceKey, f, i, j};
        if (j == 0) key = edge_key(f, 0, i, N);
        else if (i == N) key = edge_key(f, 1, j, N);
        else if (j == N) key = edge_key(f, 2, N - i, N);
        else if (i == 0) key = edge_key(f, 3, N - j, N);
        id[size_t(j * (N + 1) + i)] = point(key, f, double(i) / N, double(j) / N);
      }
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
        quad(f, id[size_t(j * (N + 1) + i)], id[size_t(j * (N + 1) + i + 1)], id[size_t((j + 1) * (N + 1) + i + 1)],
             id[size_t((j + 1) * (N + 1) + i)]);
  }

  void triangle_face(Index f, int N) {
    here.clear();
    auto at = [N](int i, int j) { return size_t(j * (N + 1) + i); };
    std::vector<Index> id(size_t((N + 1) * (N + 1)), kNone);
    for (int j = 0; j <= N; ++j)
      for (int i = 0; i + j <= N; ++i) {
        Key key{kFaceKey, f, i, j};
        if (j == 0) key = edge_key(f, 0, i, N);
        else if (i + j == N) key = edge_key(f, 1, j, N);
        else if (i == 0) key = edge_key(f, 2, N - j, N);
        id[at(i, j)] = point(key, f, double(i) / N, double(j) / N);
      }
    for (int j = 0; j < N; ++j)
      for (int i = 0; i + j < N; ++i) {
        triangle(f, id[at(i, j)], id[at(i + 1, j)], id[at(i, j + 1)]);
        if (i + j + 1 < N) triangle(f, id[at(i + 1, j)], id[at(i + 1, j + 1)], id[at(i, j + 1)]);
      }
  }

  // Sub-face q of an n-gon: corner (0,0) at vertex q, side t = 0 the first half of edge q,
  // side s = 0 the second half of edge q - 1, side s = 1 the spoke from the middle of edge
  // q to the centre (which is sub-face q + 1's side t = 1), side t = 1 the spoke from the
  // middle of edge q - 1 (sub-face q - 1's side s = 1).
  void sub_faces(Index f, int N) {
    const int n = base.face_size(f), h = N / 2, columns = sub_face_columns(n);
    for (int q = 0; q < n; ++q) {
      here.clear();
      const int prev = (q + n - 1) % n;
      std::vector<Index> id(size_t((h + 1) * (h + 1)));
      for (int j = 0; j <= h; ++j)
        for (int i = 0; i <= h; ++i) {
          Key key{kFaceKey, f, n + q, j * (h + 1) + i};  // inside the sub-face
          if (i == h && j == h) key = {kFaceKey, f, -1, 0};             // the centre
          else if (j == 0) key = edge_key(f, q, i, N);                   // edge q from vertex q
          else if (i == 0) key = edge_key(f, prev, N - j, N);            // edge q - 1 towards vertex q
          else if (i == h) key = {kFaceKey, f, q, j};                     // spoke q, j from the edge middle
          else if (j == h) key = {kFaceKey, f, prev, i};                  // spoke q - 1
          const double u = (q % columns) + 0.5 * i / h, v = (q / columns) + 0.5 * j / h;
          id[size_t(j * (h + 1) + i)] = point(key, f, u, v);
        }
      for (int j = 0; j < h; ++j)
        for (int i = 0; i < h; ++i)
          quad(f, id[size_t(j * (h + 1) + i)], id[size_t(j * (h + 1) + i + 1)], id[size_t((j + 1) * (h + 1) + i + 1)],
               id[size_t((j + 1) * (h + 1) + i)]);
    }
  }
};

// What sampling holds at its peak per sample point, in address space (what ulimit -v
// counts; the writers' copies come after the peak, so every output format needs the same):
// the grid's keys, (u, v), faces and corners, then positions, normals and the mesh made of
// them. Measured as the least `ulimit -v` with which `subdiv evaluate --samples N` succeeds,
// less the process's size when it checks (54 MiB): 381 B for --samples 420 on the cube
// (1.06 M points), 371 B for 300, 355 B on the 24-quad tube without UVs, 337 B on the
// octahedron under Loop, 307 B on the pyramid (sub-faces); 0.24 kB was counted before, and a
// run between the two ran out of memory half-way.
constexpr double kBytesPerSample = 400;
// And per face-varying channel sampled on it too (its own grid, values and corner indices):
// 270 B measured for --samples 300 on examples/meshes/textured-tube.obj (one 2-component
// channel: 625 B per point against 355 B with its vt lines removed).
constexpr double kBytesPerChannelSample = 300;

}  // namespace

std::array<double, 3> limit_normal(const LimitSurface& s, const SurfaceSample& sample, LimitSample& p, Index face,
                                   double u, double v, double negligible) {
  if (!p.has_derivatives) {
    // Towards the middle of the point's face, or of its sub-face's tile (face_domain.h).
    const int n = s.base().face_size(face);
    double cu = n == 3 && s.triangles() ? 1.0 / 3 : 0.5, cv = cu;
    if (!s.triangles() && n != 4) {
      double col = std::floor(u), row = std::floor(v);
      if (u - col > 0.75) col += 1;
      if (v - row > 0.75) row += 1;
      cu = col + 0.25, cv = row + 0.25;
    }
    const double t = 1e-9;
    sample(face, u + t * (cu - u), v + t * (cv - v), p);
    // No derivatives at all (a dual scheme without the biquadratic closed form, dual_limit.h).
    if (!p.has_derivatives) return {0, 0, 0};
  }
  return unit_normal(p.du, p.dv, negligible);
}

std::string segments_out_of_range(int N) {
  if (N >= 1 && N <= kMaxSegments) return {};
  if (N < 1) return fmt::format("give 1 to {} segments per face edge (1: each face's corners only)", kMaxSegments);
  return fmt::format("give 1 to {} segments per face edge: {} already make a million points per quad face; for a "
                     "finer mesh of the limit refine first (`subdiv refine MESH -l L --limit`) and sample that",
                     kMaxSegments, kMaxSegments);
}

void check_segments(int N) {
  if (const std::string why = segments_out_of_range(N); !why.empty())
    throw OptionError(fmt::format("{{samples}} {}: {}", N, why));
}

// N up to 1024 per edge on a large mesh asks for billions of points.
void check_samples_fit(const Level& base, bool triangles, int N, size_t face_varying_channels) {
  check_segments(N);
  double points = 0;
  const double half = double(N / 2) + 1;
  for (Index f = 0; f < base.face_count(); ++f) {
    if (base.is_hole(f)) continue;
    const int k = base.face_size(f);
    points += triangles ? (N + 1.0) * (N + 2.0) / 2 : k == 4 ? (N + 1.0) * (N + 1.0) : k * half * half;
  }
  const double need = points * (kBytesPerSample + kBytesPerChannelSample * double(face_varying_channels));
  const MemoryBudget have = available_memory();
  if (need > have.bytes) {
    const auto [need_text, have_text] = byte_sizes_compared(need, have.bytes);
    throw OptionError(fmt::format("{{samples}} {}: {:.3g} sample points would need about {}, but only {} of memory is "
                                  "available (limited by {}); ask for fewer samples per edge",
                                  N, points, need_text, have_text, have.source));
  }
}

Tessellation tessellation_grid(const Level& topology, const Level& base, bool triangles, int N) {
  check_samples_fit(base, triangles, N);
  Builder b{topology, {}, {}, {}};
  for (Index f = 0; f < base.face_count(); ++f) {
    if (base.is_hole(f)) continue;
    const int k = base.face_size(f);
    if (triangles) b.triangle_face(f, N);
    else if (k == 4) b.quad_face(f, N);
    else {
      if (N % 2)
        throw OptionError(fmt::format("{{samples}} {}: face {} has {} corners, whose sub-faces take N/2 segments "
                                      "each so that its edges have N: use an even N", N, f, k));
      b.sub_faces(f, N);
    }
  }
  return std::move(b.out);
}

Tessellation tessellate(const LimitSurface& surface, int N, const SurfaceSample& sample, double negligible) {
  Tessellation out = tessellation_grid(surface.base(), surface.base(), surface.triangles(), N);
  out.positions.assign(size_t(out.point_count()) * 3, 0.0);
  out.normals.assign(out.positions.size(), 0.0);
  // One sample per thread, its memory reused point after point.
  tbb::enumerable_thread_specific<LimitSample> samples;
  parallel_for_all(out.point_count(), [&](Index i) {
    const Index f = out.uv_face[size_t(i)];
    const double u = out.uv[size_t(2 * i)], v = out.uv[size_t(2 * i + 1)];
    LimitSample& p = samples.local();
    sample(f, u, v, p);
    for (int c = 0; c < 3; ++c) out.positions[size_t(3 * i + c)] = p.position[size_t(c)];
    const auto n = limit_normal(surface, sample, p, f, u, v, negligible);
    for (int c = 0; c < 3; ++c) out.normals[size_t(3 * i + c)] = n[size_t(c)];
  }, LoopProgress::Told);
  return out;
}

std::string zero_normals_warning(std::span<const double> normals, std::span<const Index> faces,
                                 std::span<const double> uv) {
  size_t count = 0, first = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    const double* n = &normals[3 * i];
    if (n[0] != 0 || n[1] != 0 || n[2] != 0) continue;
    if (count++ == 0) first = i;
  }
  if (count == 0) return {};
  return fmt::format("the limit surface has no normal at {} of {} points (the first at face {}, (u, v) = ({}, {})): "
                     "its tangents are parallel or zero there (coincident control points, a surface folded flat) or "
                     "the scheme gives no derivatives; their Normals are (0, 0, 0)",
                     count, faces.size(), faces[first], uv[2 * first], uv[2 * first + 1]);
}

Tessellation tessellate(const LimitSurface& surface, std::span<const double> positions, int N) {
  return tessellate(
      surface, N,
      [&](Index face, double u, double v, LimitSample& out) { surface.evaluate_into(face, u, v, positions, 3, 1, out); },
      negligible_tangent(positions));
}

}  // namespace subdiv
