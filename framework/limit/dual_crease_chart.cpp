#include "framework/limit/dual_crease_chart.h"

#include <array>
#include <cmath>
#include <iterator>
#include <map>

#include <fmt/format.h>

#include "framework/engine/refiner.h"

#include "framework/features/dual_features.h"
#include "framework/features/sharpness.h"
#include "framework/limit/dual_crease_strip.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

constexpr Uv kCorner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

Index corner_edge(const Level& L, Index f, int corner) { return L.face_edges[size_t(L.face_offsets[f] + corner)]; }

}  // namespace

bool edge_infinitely_sharp(const Level& L, Index e) {
  return L.edge_on_boundary(e) || L.edge_sharp(e) >= kInfinitelySharp;
}

namespace {

std::string vertex_problem(const Level& L, Index v) {
  const int sharp = dual_sharp_edge_count(L, v);
  const float vs = L.vertex_sharp(v);
  if (vs >= 1.f && vs < kInfinitelySharp)
    return fmt::format("vertex {} has sharpness {} (a semi-sharp corner)", v, vs);
  if (dual_collapses(L, v)) return {};  // faces_refused_at: the corners not evaluated refuse their faces only
  if (sharp == 0) return {};
  if (sharp == 1) return fmt::format("vertex {} ends a crease (a dart)", v);
  float s[2] = {0, 0};
  int k = 0;
  for (Index e : L.ring_edges(v))
    if (dual_sharp_edge(L, e)) s[k++] = edge_infinitely_sharp(L, e) ? kInfinitelySharp : L.edge_sharp(e);
  if (s[0] != s[1])
    return fmt::format("crease vertex {} joins sharp edges of sharpness {} and {} (a crease whose sharpness varies "
                       "along it decays unevenly, which is not evaluated yet)",
                       v, s[0], s[1]);
  return {};
}

std::string face_problem(const Level& L, Index f) {
  const auto run = crease_run(L, f);
  if (!run) {
    if (crease_strip(L, f)) return {};
    return fmt::format("face {} lies between two creases (its crease corners are not one run), and only quads "
                       "between creases on opposite sides are evaluated so far, with smooth other edges and no corner "
                       "of the mesh at their corners unless both creases are infinitely sharp",
                       f);
  }
  if (run->length == 0) return {};
  const int n = L.face_size(f);
  if (n != 4)
    return fmt::format("face {} has {} sides and a corner on a boundary or crease (only quads next to boundaries and "
                       "creases so far)",
                       f, n);
  if (run->length == 2 && dual_sharp_edge(L, corner_edge(L, f, run->first))) return {};
  if (run->length == 3 && dual_sharp_edge(L, corner_edge(L, f, run->first)) &&
      dual_sharp_edge(L, corner_edge(L, f, (run->first + 1) % n)) &&
      dual_collapses(L, L.face(f)[size_t((run->first + 1) % n)]))
    return {};
  return fmt::format("face {} has {} of its {} corners on a boundary or crease (a face between creases)", f,
                     run->length, n);
}

}  // namespace

bool is_crease_corner(const Level& L, Index f, int corner) {
  const int n = L.face_size(f);
  return dual_collapses(L, L.face(f)[size_t(corner)]) || dual_sharp_edge(L, corner_edge(L, f, corner)) ||
         dual_sharp_edge(L, corner_edge(L, f, (corner + n - 1) % n));
}

namespace {

std::optional<CreaseRun> run_of(const std::vector<bool>& in) {
  const int n = int(in.size());
  int count = 0, starts = 0, first = 0;
  for (int i = 0; i < n; ++i) {
    count += in[size_t(i)];
    if (in[size_t(i)] && !in[size_t((i + n - 1) % n)]) ++starts, first = i;
  }
  if (count == 0) return CreaseRun{};
  if (count == n || starts != 1) return std::nullopt;
  return CreaseRun{first, count};
}

}  // namespace

std::optional<CreaseRun> crease_run(const Level& L, Index f) {
  std::vector<bool> in(size_t(L.face_size(f)));
  for (int i = 0; i < L.face_size(f); ++i) in[size_t(i)] = is_crease_corner(L, f, i);
  return run_of(in);
}

std::optional<CreaseRun> made_on_crease_run(const Level& parent, const Level& child, const ChildOrigins& o, Index face) {
  const auto g = child.face(face);
  std::vector<bool> in(g.size());
  for (size_t k = 0; k < g.size(); ++k) {
    const size_t x = size_t(g[k]);
    in[k] = o.kind[x] == OriginKind::Corner && is_crease_corner(parent, o.parent[x], int(o.local[x]));
  }
  return run_of(in);
}

QuadrantChart half_quad_quadrant(CreaseRun run, int corner) {
  auto crease = [&](int i) { return ((i - run.first + 4) % 4) < run.length; };
  auto towards = [&](int next) {
    const Uv& c = kCorner[corner];
    const Uv& x = kCorner[next];
    const Uv end = crease(next) ? x : Uv{(c[0] + x[0]) / 2, (c[1] + x[1]) / 2};
    return Uv{end[0] - c[0], end[1] - c[1]};
  };
  return {kCorner[corner], towards((corner + 1) % 4), towards((corner + 3) % 4)};
}

std::vector<std::pair<int, double>> crease_run_middle(CreaseRun run, int face_size) {
  const int half = (run.length - 1) / 2;
  if (run.length % 2 == 1) return {{(run.first + half) % face_size, 1.0}};
  return {{(run.first + half) % face_size, 0.5}, {(run.first + half + 1) % face_size, 0.5}};
}

Index other_crease_neighbour(const Level& L, Index x, Index not_to) {
  for (Index e : L.ring_edges(x)) {
    if (!dual_sharp_edge(L, e)) continue;
    const Index a = L.edge_vertices[size_t(2 * e)], b = L.edge_vertices[size_t(2 * e + 1)];
    const Index y = a == x ? b : a;
    if (y != not_to) return y;
  }
  return kNone;
}

namespace {

// The clamped quadratic B-spline's three basis functions on its first knot interval [0, 1]
// (knots 0, 0, 0, 1, 2): the corner's, its neighbour's, the next one's.
std::array<double, 3> clamped_first_interval(double t) {
  return {(1 - t) * (1 - t), 2 * t - 1.5 * t * t, 0.5 * t * t};
}

}  // namespace

std::vector<std::pair<Index, double>> crease_side_limit(const Level& L, Index f, CreaseRun run, int corner,
                                                        bool towards_next, double s) {
  const auto g = L.face(f);
  const int n = int(g.size());
  const int xi = towards_next ? (corner + 1) % n : (corner + n - 1) % n;
  auto in_run = [&](int i) { return ((i - run.first + n) % n) < run.length; };
  if (!in_run(xi)) return {};
  const Index X = g[size_t(xi)];
  if (run.length == 3) {
    const Index K = g[size_t((run.first + 1) % n)];
    const Index next = other_crease_neighbour(L, X, K);
    if (next == kNone) return {};
    const double t = (1 - s) / 2;
    if (dual_collapses(L, next))  // a crease of one vertex between two corners: a quadratic Bezier curve
      return {{K, (1 - t) * (1 - t)}, {X, 2 * t * (1 - t)}, {next, t * t}};
    const auto w = clamped_first_interval(t);
    return {{K, w[0]}, {X, w[1]}, {next, w[2]}};
  }
  const Index Y = g[size_t(xi == run.first ? (run.first + 1) % n : run.first)];
  const Index prev = other_crease_neighbour(L, X, Y);
  if (prev == kNone) return {};
  const double t = s / 2;
  if (dual_collapses(L, prev)) {
    const auto w = clamped_first_interval(0.5 + t);
    return {{prev, w[0]}, {X, w[1]}, {Y, w[2]}};
  }
  return {{prev, 0.5 * (0.5 - t) * (0.5 - t)}, {X, 0.75 - t * t}, {Y, 0.5 * (0.5 + t) * (0.5 + t)}};
}

bool crease_run_infinitely_sharp(const Level& L, Index f, CreaseRun run) {
  const int n = L.face_size(f);
  for (int k = 0; k + 1 < run.length; ++k)
    if (!edge_infinitely_sharp(L, corner_edge(L, f, (run.first + k) % n))) return false;
  return true;
}

std::string crease_middles_kept(const Scheme& scheme, const FeatureOptions& features, bool* chaikin, bool* middles) {
  constexpr int nx = 6, ny = 5;
  std::vector<Index> offsets{0}, corners;
  auto id = [](int i, int j) { return Index(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      for (Index v : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}) corners.push_back(v);
      offsets.push_back(Index(corners.size()));
    }
  const Level grid = build_level(Index((nx + 1) * (ny + 1)), offsets, corners);
  if (middles) *middles = true;
  RefineOptions ro;
  ro.levels = 1;
  ro.features = features;
  Hierarchy h;
  try {
    h = refine(scheme, grid, ro);
  } catch (const Error& e) {
    return std::string("one step of the scheme on an open grid fails: ") + e.what();
  }
  if (!h.linear() || h.stencils.empty()) return "the scheme's rules are not linear";
  const StencilTable& table = h.stencils[0];
  const Level& child = h.levels[1];
  auto row = [&](Index v) {
    std::map<Index, double> r;
    for (Index k = table.offsets[size_t(v)]; k < table.offsets[size_t(v) + 1]; ++k)
      r[table.indices[size_t(k)]] += table.weights[size_t(k)];
    return r;
  };
  auto equal = [](const std::map<Index, double>& r, const std::map<Index, double>& e) {
    double off = 0;
    for (const auto& [v, w] : r) off += std::abs(w - (e.count(v) ? e.at(v) : 0.0));
    for (const auto& [v, w] : e) off += r.count(v) ? 0.0 : std::abs(w);
    return off < 1e-12;
  };
  auto is_corner = [&](Index v) { return grid.incident_face_count(v) == 1; };
  for (Index e = 0; e < grid.edge_count(); ++e) {
    if (!grid.edge_on_boundary(e)) continue;
    const Index p = grid.edge_vertices[size_t(2 * e)], q = grid.edge_vertices[size_t(2 * e + 1)];
    if (is_corner(p) || is_corner(q)) continue;
    bool found = false;
    for (Index c = 0; c < child.edge_count() && !found; ++c) {
      if (!child.edge_on_boundary(c)) continue;
      auto r = row(child.edge_vertices[size_t(2 * c)]);
      for (const auto& [v, w] : row(child.edge_vertices[size_t(2 * c + 1)])) r[v] += w;
      found = equal(r, {{p, 1.0}, {q, 1.0}});
    }
    if (!found) {
      if (!middles)
        return "its crease rule does not keep the middle of every crease edge (the crease is not Chaikin's curve "
               "after the split's passes)";
      *middles = false;
    }
  }
  for (Index v = 0; v < grid.vertex_count; ++v) {
    if (!is_corner(v)) continue;
    bool found = false;
    for (Index c = 0; c < child.vertex_count && !found; ++c) found = equal(row(c), {{v, 1.0}});
    if (!found) return "its corners do not stay";
  }
  // Chaikin's cuts 3/4, 1/4 on every boundary edge, the middle of an edge at a corner.
  if (chaikin) {
    *chaikin = true;
    for (Index c = 0; c < child.vertex_count && *chaikin; ++c) {
      if (!child.on_boundary(c)) continue;
      const auto r = row(c);
      if (r.size() == 1) continue;  // a corner's point
      const Index a = r.begin()->first, b = std::next(r.begin())->first;
      if (r.size() != 2 || find_edge(grid, a, b) == kNone || !grid.edge_on_boundary(find_edge(grid, a, b))) {
        *chaikin = false;
        break;
      }
      if (is_corner(a) || is_corner(b))
        *chaikin = equal(r, {{a, 0.5}, {b, 0.5}});
      else
        *chaikin = equal(r, {{a, 0.75}, {b, 0.25}}) || equal(r, {{a, 0.25}, {b, 0.75}});
    }
  }
  return {};
}

namespace {

// The faces on the two sides of v's crease: v has two edges for which `sharp` holds.
template <class Sharp>
std::array<int, 2> crease_sides(const Level& L, Index v, Sharp sharp) {
  if (L.on_boundary(v)) return {L.incident_face_count(v), 0};
  const auto ring = L.ring_edges(v);
  const int n = int(ring.size());
  int first = -1, second = -1;
  for (int k = 0; k < n; ++k)
    if (sharp(ring[size_t(k)])) (first < 0 ? first : second) = k;
  return {second - first, n - (second - first)};
}

VertexRefusal sides_refusal(const Level& L, Index v, std::array<int, 2> sides, const std::string& what) {
  if (sides[0] == 2 && (sides[1] == 2 || L.on_boundary(v))) return {};
  VertexRefusal r;
  r.what = L.on_boundary(v) ? fmt::format("boundary vertex {}, which has {} faces", v, sides[0])
                            : fmt::format("crease vertex {}, which has {} and {} faces on the sides of its crease", v,
                                          sides[0], sides[1]);
  r.what = what.empty() ? r.what : fmt::format("{} ({})", what, r.what);
  if (sides[0] == 1 || (sides[1] == 1 && !L.on_boundary(v)))
    r.why = "with one face on a side, that face's corner makes two crease points in one quadrant (a layout for them "
            "is left to do)";
  else
    r.why = "with three or more faces on a side, the faces between the two end faces touch the crease at the vertex "
            "only and split their edges there differently from the end faces, so nested quadrants are not "
            "continuous at the vertex, and every step doubles such vertices (docs/limit.md)";
  return r;
}

// A corner of the dual split (dual_collapses) keeps its faces while it is one: all its face
// corners are one point, a sharp edge has no E-face and a corner no V-face. Its faces are
// evaluated when every edge there is sharp and the semi-sharp ones decay together (one
// sharpness, no vertex sharpness): the corner then becomes the vertex its infinitely sharp
// edges make — a smooth vertex (none), or a boundary or crease vertex (two) — with the same
// faces, laid out by their shorter crease runs from then on (dual_limit.cpp, follow_decay).
VertexRefusal corner_refusal(const Level& L, Index v) {
  const float vs = L.vertex_sharp(v);
  if (vs >= 1.f && vs < kInfinitelySharp) return {};  // a semi-sharp corner: refused for the whole mesh
  int lasting = 0;
  float semi = 0;
  for (Index e : L.ring_edges(v)) {
    if (edge_infinitely_sharp(L, e)) {
      ++lasting;
      continue;
    }
    const float s = L.edge_sharp(e);
    const bool grows = s < 1.f || (semi != 0 && s != semi) || vs >= kInfinitelySharp;
    if (grows)
      return {fmt::format("corner vertex {}", v),
              s < 1.f || vs >= kInfinitelySharp
                  ? "it has an edge that is not sharp (now or once its sharpness has decayed): the E-face of such an "
                    "edge loses a corner to the corner's point, so its ring of faces grows every level and no "
                    "neighbourhood repeats"
                  : fmt::format("its semi-sharp edges have sharpness {} and {}, so they decay at different levels and "
                                "its ring of faces grows once one of them is smooth",
                                semi, s)};
    semi = s;
  }
  if (semi == 0 || lasting == 0) return {};  // infinitely sharp, or smooth once its edges have decayed
  if (lasting == 2)
    return sides_refusal(L, v, crease_sides(L, v, [&](Index e) { return edge_infinitely_sharp(L, e); }),
                         fmt::format("corner vertex {} once its semi-sharp edges have decayed", v));
  return {fmt::format("corner vertex {}", v),
          fmt::format("{} of its edges are infinitely sharp and the others semi-sharp: once those have decayed it is "
                      "{}",
                      lasting,
                      lasting == 1 ? "the end of a crease (a dart)"
                                   : "a corner with smooth edges, whose ring of faces grows every level")};
}

}  // namespace

VertexRefusal faces_refused_at(const Level& L, Index v) {
  if (dual_collapses(L, v)) return corner_refusal(L, v);
  if (dual_sharp_edge_count(L, v) == 0 && !L.on_boundary(v) && L.incident_face_count(v) == 2)
    return {fmt::format("interior vertex {} of valence 2", v),
            "the dual split's face for it would have two sides, so the new points at its corners are not smooth "
            "points of four faces, which the quadrants of its faces need"};
  if (dual_sharp_edge_count(L, v) != 2) return {};
  return sides_refusal(L, v, crease_sides(L, v, [&](Index e) { return dual_sharp_edge(L, e); }), {});
}

std::string dual_crease_unsupported(const Level& base) {
  // Holes change no rule, only which faces have a surface: only what the faces that are kept
  // touch must be covered.
  for (Index v = 0; v < base.vertex_count; ++v) {
    bool kept = false;
    for (Index f : base.ring_faces(v)) kept = kept || !base.is_hole(f);
    if (!kept) continue;
    if (std::string why = vertex_problem(base, v); !why.empty()) return why;
  }
  // The faces at a vertex faces_refused_at names are refused one by one.
  std::vector<bool> refused(size_t(base.face_count()), false);
  for (Index v = 0; v < base.vertex_count; ++v)
    if (!faces_refused_at(base, v).what.empty())
      for (Index f : base.ring_faces(v)) refused[size_t(f)] = true;
  for (Index f = 0; f < base.face_count(); ++f)
    if (!base.is_hole(f) && !refused[size_t(f)])
      if (std::string why = face_problem(base, f); !why.empty()) return why;
  return {};
}

}  // namespace subdiv
