#include "framework/analysis/surface/local_patch.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "framework/refine/child_tags.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

const double kPi = std::acos(-1.0);

int ring_face_index(const Level& L, Index v, Index f) {
  const auto faces = L.ring_faces(v);
  for (size_t i = 0; i < faces.size(); ++i)
    if (faces[i] == f) return int(i);
  return 0;
}

// x mod n for 0 <= x < 2 n, without a division (the labelling's inner loops take it per corner).
int below(int x, int n) { return x >= n ? x - n : x; }

// Sharpness as signatures see it: infinitely sharp is one value, boundary edges -1.
double sig_sharpness(float s) { return s >= kInfinitelySharp ? double(kInfinitelySharp) : double(s); }

// Labels around the centre; with `expected`, compares the signature on the fly instead of
// storing it and returns false at the first difference.
// With `quad_grid`, also checks that the neighbourhood is untagged regular quad grid as it
// goes (quad_grid_labelled) and returns false at the first vertex or face that is not.
// With `ordered` false, each vertex's faces are scanned from its first ring face instead of
// the face it was reached through: the same vertices at the same distances (breadth-first,
// ring by ring) and the same checks, in another order within a ring, without looking up
// where each new vertex's scan starts.
bool label_into(Labelling& out, const Level& L, CentreKind kind, Index centre, int start, int radius,
                bool with_signature, const std::vector<double>* expected = nullptr, bool quad_grid = false,
                bool ordered = true) {
  // Only the entries set by the last use are cleared; the array only grows (entries past
  // this level's vertices stay kNone), so a reused labelling costs its neighbourhood only.
  for (Index v : out.vertices)
    if (size_t(v) < out.label_of.size()) out.label_of[size_t(v)] = kNone;
  if (out.label_of.size() < size_t(L.vertex_count)) out.label_of.resize(size_t(L.vertex_count), kNone);
  out.vertices.clear(), out.distance.clear(), out.signature.clear();
  // The grid check reads each face once: a face met again has all its corners labelled and
  // its checks made (the signature, which records each face from each corner, does not skip).
  for (Index f : out.faces_met) out.face_met[size_t(f)] = 0;
  out.faces_met.clear();
  if (quad_grid && out.face_met.size() < size_t(L.face_count())) out.face_met.resize(size_t(L.face_count()), 0);
  std::vector<int>& entry = out.entry;
  entry.clear();
  size_t checked = 0;
  bool same = true;
  struct Sink {
    std::vector<double>& sig;
    const std::vector<double>* expected;
    size_t& checked;
    bool& same;
    void push_back(double x) {
      if (!expected) return sig.push_back(x);
      if (checked >= expected->size() || (*expected)[checked] != x) same = false;
      ++checked;
    }
  };
  auto add = [&](Index v, int d, int e) {
    out.label_of[size_t(v)] = Index(out.vertices.size());
    out.vertices.push_back(v);
    out.distance.push_back(d);
    entry.push_back(e);
  };
  if (kind == CentreKind::Vertex) {
    const int faces = std::max(1, L.incident_face_count(centre));
    add(centre, 0, ((start % faces) + faces) % faces);
  } else {
    const auto corners = L.face(centre);
    const int k = int(corners.size());
    for (int i = 0; i < k; ++i) {
      const Index v = corners[size_t(((start + i) % k + k) % k)];
      add(v, 0, ring_face_index(L, v, centre));
    }
  }
  Sink sig{out.signature, expected, checked, same};
  for (size_t q = 0; q < out.vertices.size() && same; ++q) {
    const Index v = out.vertices[q];
    const int d = out.distance[q];
    if (quad_grid && (L.vertex_sharp(v) != 0.f ||
                      (d < radius && (L.valence(v) != 4 || L.on_boundary(v) || L.incident_face_count(v) != 4))))
      return false;
    if (with_signature) {
      sig.push_back(L.valence(v));
      sig.push_back(L.on_boundary(v) ? 1 : 0);
      sig.push_back(sig_sharpness(L.vertex_sharp(v)));
    }
    if (d >= radius) continue;
    const auto faces = L.ring_faces(v);
    const int F = int(faces.size());
    if (with_signature) sig.push_back(F);
    const Index first = L.vertex_face_offsets[v];
    for (int t = 0; t < F; ++t) {
      const int fi = below(entry[q] + t, F);
      const Index f = faces[size_t(fi)];
      if (quad_grid) {
        if (out.face_met[size_t(f)]) continue;
        out.face_met[size_t(f)] = 1;
        out.faces_met.push_back(f);
      }
      const int c = L.vertex_face_corner[size_t(first + fi)];
      const auto corners = L.face(f);
      const auto edges = L.face_edge_list(f);
      const int k = int(corners.size());
      if (quad_grid) {
        if (k != 4 || L.is_hole(f)) return false;
        // A level without edge sharpness has none to find: its faces' edges are not read.
        if (!L.edge_sharpness.empty())
          for (Index e : edges)
            if (L.edge_sharp(e) != 0.f) return false;
      }
      if (with_signature) sig.push_back(k);
      for (int i = 1; i < k; ++i) {
        const Index w = corners[size_t(below(c + i, k))];
        if (out.label_of[size_t(w)] == kNone) add(w, d + 1, ordered ? ring_face_index(L, w, f) : 0);
        if (with_signature) sig.push_back(out.label_of[size_t(w)]);
      }
      if (with_signature)
        for (int i = 0; i < k; ++i) {
          const Index e = edges[size_t(below(c + i, k))];
          sig.push_back(L.edge_on_boundary(e) ? -1.0 : sig_sharpness(L.edge_sharp(e)));
        }
    }
  }
  return same && (!expected || checked == expected->size());
}

Labelling label(const Level& L, CentreKind kind, Index centre, int start, int radius, bool with_signature) {
  Labelling out;
  label_into(out, L, kind, centre, start, radius, with_signature);
  return out;
}

// Per-thread scratch for extract_neighbourhood, indexed by the original level's vertices
// and faces: every entry is kNone / 0 between calls, so a call touches only its own
// neighbourhood and extracting around every face of a level is linear in the level, not
// quadratic. Thread-local because preparation runs in parallel (TBB).
struct ExtractScratch {
  Labelling lab;
  std::vector<Index> local_of;  // original vertex -> new vertex, or kNone
  std::vector<char> taken;      // original face -> taken
  std::vector<Index> touched_vertices, touched_faces;
  std::vector<char> seen;  // original vertex -> listed in corners_now (0 between uses)
  std::vector<Index> corners_now;

  void fit(const Level& L) {
    if (local_of.size() < size_t(L.vertex_count)) local_of.resize(size_t(L.vertex_count), kNone);
    if (seen.size() < size_t(L.vertex_count)) seen.resize(size_t(L.vertex_count), 0);
    if (taken.size() < size_t(L.face_count())) taken.resize(size_t(L.face_count()), 0);
  }
  void clear() {
    for (Index v : touched_vertices) local_of[size_t(v)] = kNone;
    for (Index f : touched_faces) taken[size_t(f)] = 0;
    touched_vertices.clear(), touched_faces.clear();
  }
};

ExtractScratch& extract_scratch() {
  thread_local ExtractScratch scratch;
  return scratch;
}

// Clears the scratch on every way out, exceptions included, so the next call finds it clean.
struct ScratchGuard {
  ExtractScratch& s;
  ~ScratchGuard() { s.clear(); }
};

}  // namespace

std::string LocalConfig::describe() const {
  std::string s;
  if (centre == CentreKind::Face && !boundary && sharp.empty() && !corner) return fmt::format("face of size {}", valence);
  if (boundary) s = "boundary ";
  if (!sharp.empty()) {
    s += sharp.size() == 1 ? "dart " : sharp.size() == 2 ? "crease " : "corner ";
  }
  if (corner) s += "corner-tagged ";
  s += fmt::format("valence {}", valence);
  if (!sharp.empty()) {
    s += " (sharp ring edges";
    for (int p : sharp) s += fmt::format(" {}", p);
    s += ")";
  }
  // A dual scheme is analysed at the face its first sector becomes.
  if (centre == CentreKind::Face) s += ", its sector's face";
  return s;
}

int Labelling::count_within(int k) const {
  return int(std::upper_bound(distance.begin(), distance.end(), k) - distance.begin());
}

Labelling label_neighbourhood(const Level& level, CentreKind kind, Index centre, int start, int radius) {
  return label(level, kind, centre, start, radius, true);
}

void label_neighbourhood(Labelling& reuse, const Level& level, CentreKind kind, Index centre, int start, int radius) {
  label_into(reuse, level, kind, centre, start, radius, true);
}

bool matches_neighbourhood(Labelling& reuse, const Level& level, CentreKind kind, Index centre, int start, int radius,
                           const std::vector<double>& signature) {
  return label_into(reuse, level, kind, centre, start, radius, true, &signature);
}

namespace {

bool quad_grid_check(Labelling& reuse, const Level& level, Index face, int radius, bool ordered) {
  if (level.face_size(face) != 4 || level.is_hole(face)) return false;
  if (!label_into(reuse, level, CentreKind::Face, face, 0, radius, false, nullptr, true, ordered)) return false;
  // The breadth-first search unrolls the grid from the face; it reaches as many vertices as
  // the plane's (2 radius + 2)^2 only when no two of its paths meet again (a torus or
  // cylinder narrower than the neighbourhood wraps around).
  const size_t side = size_t(2 * radius + 2);
  return reuse.vertices.size() == side * side;
}

}  // namespace

bool quad_grid_labelled(Labelling& reuse, const Level& level, Index face, int radius) {
  return quad_grid_check(reuse, level, face, radius, true);
}

bool quad_grid_distances(Labelling& reuse, const Level& level, Index face, int radius) {
  return quad_grid_check(reuse, level, face, radius, false);
}

Patch make_vertex_patch(PatchCells cells, const LocalConfig& c, int R) {
  const int n = c.valence;
  const bool quads = cells == PatchCells::Quads;
  if (n < 2 || n > kMaxPatchValence)
    throw Error(fmt::format("valence {} cannot be analysed: valences 2..{} are (2 inside a quad mesh or on a "
                            "boundary); split the vertex's fan with extra edges to bring it within {}",
                            n, kMaxPatchValence, kMaxPatchValence));
  // Two triangles around an interior vertex share both its edges and then their third one
  // too: they close into a two-triangle sphere, with no regular surroundings to analyse.
  if (n == 2 && !c.boundary && !quads)
    throw Error("interior valence 2 cannot be analysed in a triangle mesh: the vertex's two triangles share all "
                "three edges, a closed two-triangle sphere with no regular surroundings (use 3 or more inside, or 2 "
                "on a boundary)");
  if (R < 2) throw Error("a synthetic patch needs at least 2 rings");
  const int sectors = c.boundary ? n - 1 : n;
  // Rays at equal angles; a boundary fan keeps regular sectors when it can, spread over pi.
  const double regular = quads ? kPi / 2 : kPi / 3;
  const double sector_angle = c.boundary ? std::min(regular, kPi / double(sectors)) : 2 * kPi / double(n);
  std::vector<double> ux(static_cast<size_t>(n)), uy(static_cast<size_t>(n));
  for (int r = 0; r < n; ++r) ux[size_t(r)] = std::cos(r * sector_angle), uy[size_t(r)] = std::sin(r * sector_angle);
  // Two interior sectors at equal angles would lie on one line (their rays point opposite
  // ways). Each quarter-plane sector is then mapped by z -> z^2, rotated by pi per sector:
  // every sector a half-plane, faces of positive area, the two sides mirror images
  // (Karciauskas & Peters 2009 find z^2 as the characteristic ring of valence 2). The
  // analysis reads positions only to orient and align the patch, so any embedding does.
  const bool squared = n == 2 && !c.boundary;
  auto place = [&](int r0, double a, double b, std::vector<double>& xy) {
    if (squared) {
      const double sign = r0 == 0 ? 1.0 : -1.0;
      xy.push_back(sign * (a * a - b * b)), xy.push_back(sign * 2 * a * b);
      return;
    }
    const int r1 = (r0 + 1) % n;
    xy.push_back(a * ux[size_t(r0)] + b * ux[size_t(r1)]);
    xy.push_back(a * uy[size_t(r0)] + b * uy[size_t(r1)]);
  };

  Patch p;
  std::vector<double>& xy = p.xy;
  xy = {0.0, 0.0};
  // Ray points: ray r, distance a (1..R).
  std::vector<Index> ray(size_t(n * R));
  for (int r = 0; r < n; ++r)
    for (int a = 1; a <= R; ++a) {
      ray[size_t(r * R + a - 1)] = Index(xy.size() / 2);
      place(r, a, 0, xy);
    }
  std::vector<Index> offsets{0}, corners;
  for (int s = 0; s < sectors; ++s) {
    const int r0 = s, r1 = (s + 1) % n;
    // Interior points of the sector.
    std::vector<Index> inner(size_t((R + 1) * (R + 1)), kNone);
    auto point = [&](int a, int b) -> Index {
      if (a == 0 && b == 0) return 0;
      if (b == 0) return ray[size_t(r0 * R + a - 1)];
      if (a == 0) return ray[size_t(r1 * R + b - 1)];
      Index& id = inner[size_t(a * (R + 1) + b)];
      if (id == kNone) {
        id = Index(xy.size() / 2);
        place(r0, a, b, xy);
      }
      return id;
    };
    auto face = [&](std::initializer_list<Index> vs) {
      corners.insert(corners.end(), vs);
      offsets.push_back(Index(corners.size()));
    };
    for (int a = 0; a < R; ++a)
      for (int b = 0; b < R; ++b) {
        if (quads) {
          face({point(a, b), point(a + 1, b), point(a + 1, b + 1), point(a, b + 1)});
          continue;
        }
        if (a + b <= R - 1) face({point(a, b), point(a + 1, b), point(a, b + 1)});
        if (a + b <= R - 2) face({point(a + 1, b), point(a + 1, b + 1), point(a, b + 1)});
      }
  }
  // Ray points of a boundary fan's last ray belong to no sector when... (they always do:
  // sector n-2 uses ray n-1). Every point is used.
  p.level = build_level(Index(xy.size() / 2), offsets, corners);
  Level& L = p.level;
  // The ring position of ray 0 at the centre.
  const Index first = find_edge(L, 0, ray[0]);
  const auto ring = L.ring_edges(0);
  p.start = int(std::find(ring.begin(), ring.end(), first) - ring.begin());
  if (!c.sharp.empty()) {
    L.edge_sharpness.assign(size_t(L.edge_count()), 0.f);
    for (int r : c.sharp) {
      if (r < 0 || r >= n) throw Error(fmt::format("sharp ring edge {} is not in 0..{}", r, n - 1));
      Index prev = 0;
      for (int a = 1; a <= R; ++a) {
        const Index next = ray[size_t(r * R + a - 1)];
        L.edge_sharpness[size_t(find_edge(L, prev, next))] = kInfinitelySharp;
        prev = next;
      }
    }
  }
  if (c.corner) {
    L.vertex_sharpness.assign(size_t(L.vertex_count), 0.f);
    L.vertex_sharpness[0] = kInfinitelySharp;
  }
  p.centre_kind = CentreKind::Vertex;
  p.centre = 0;
  return p;
}

Patch make_face_patch(int n, int R) {
  LocalConfig c;
  c.valence = n;
  const Patch primal = make_vertex_patch(PatchCells::Quads, c, R + 1);
  const Level& P = primal.level;
  Patch p;
  p.xy.resize(size_t(2 * P.face_count()));
  for (Index f = 0; f < P.face_count(); ++f) {
    double x = 0, y = 0;
    for (Index v : P.face(f)) x += primal.xy[size_t(2 * v)], y += primal.xy[size_t(2 * v + 1)];
    p.xy[size_t(2 * f)] = x / P.face_size(f), p.xy[size_t(2 * f + 1)] = y / P.face_size(f);
  }
  std::vector<Index> offsets{0}, corners;
  Index centre = kNone;
  for (Index v = 0; v < P.vertex_count; ++v) {
    if (P.on_boundary(v)) continue;
    if (v == 0) centre = Index(offsets.size()) - 1;
    for (Index f : P.ring_faces(v)) corners.push_back(f);
    offsets.push_back(Index(corners.size()));
  }
  p.level = build_level(P.face_count(), offsets, corners);
  p.centre_kind = CentreKind::Face;
  p.centre = centre;
  p.start = 0;
  return p;
}

int conventional_start(const Level& L, Index v) {
  if (L.on_boundary(v)) return 0;
  const auto ring = L.ring_edges(v);
  for (size_t i = 0; i < ring.size(); ++i)
    if (L.edge_sharp(ring[i]) > 0.f) return int(i);
  return 0;
}

LocalConfig vertex_config(const Level& L, Index v, int first_step, bool* semi_sharp) {
  LocalConfig c;
  c.centre = CentreKind::Vertex;
  c.valence = L.valence(v);
  c.boundary = L.on_boundary(v);
  c.first_step = first_step;
  const float vs = L.vertex_sharp(v);
  c.corner = vs >= kInfinitelySharp;
  bool semi = vs > 0.f && vs < kInfinitelySharp;
  const int start = conventional_start(L, v);
  const auto ring = L.ring_edges(v);
  const int n = int(ring.size());
  for (int i = 0; i < n; ++i) {
    const Index e = ring[size_t((start + i) % std::max(1, n))];
    if (L.edge_on_boundary(e)) continue;
    const float s = L.edge_sharp(e);
    if (s >= kInfinitelySharp) c.sharp.push_back(i);
    else if (s > 0.f) semi = true;
  }
  if (semi_sharp) *semi_sharp = semi;
  return c;
}

Extracted extract_neighbourhood(const Level& L, CentreKind kind, Index centre, int radius) {
  ExtractScratch& scratch = extract_scratch();
  scratch.fit(L);
  const ScratchGuard guard{scratch};
  Labelling& lab = scratch.lab;
  label_into(lab, L, kind, centre, 0, radius, false);
  std::vector<Index>& local_of = scratch.local_of;
  std::vector<char>& taken = scratch.taken;
  Extracted out;
  std::vector<Index> faces, extra_vertices;
  auto take = [&](Index f) {
    taken[size_t(f)] = 1;
    faces.push_back(f);
    scratch.touched_faces.push_back(f);
  };
  for (size_t q = 0; q < lab.vertices.size(); ++q) {
    if (lab.distance[q] >= radius) break;
    for (Index f : L.ring_faces(lab.vertices[q]))
      if (!taken[size_t(f)]) take(f);
  }
  if (kind == CentreKind::Face && !taken[size_t(centre)]) take(centre);
  // A vertex whose taken faces form two fans would be non-manifold: take all its faces,
  // until no vertex is pinched.
  for (bool changed = true; changed;) {
    changed = false;
    // The taken faces' corners once each (marked, then sorted: a few per face, not all).
    std::vector<Index>& corners_now = scratch.corners_now;
    corners_now.clear();
    for (Index f : faces)
      for (Index v : L.face(f))
        if (!scratch.seen[size_t(v)]) scratch.seen[size_t(v)] = 1, corners_now.push_back(v);
    for (Index v : corners_now) scratch.seen[size_t(v)] = 0;
    std::sort(corners_now.begin(), corners_now.end());
    for (Index v : corners_now) {
      const auto ring = L.ring_faces(v);
      const int F = int(ring.size());
      int runs = 0, missing = 0;
      for (int i = 0; i < F; ++i) {
        const bool in = taken[size_t(ring[size_t(i)])];
        missing += in ? 0 : 1;
        const bool prev_in = i > 0 ? bool(taken[size_t(ring[size_t(i - 1)])])
                                   : (!L.on_boundary(v) && bool(taken[size_t(ring[size_t(F - 1)])]));
        if (in && !prev_in) ++runs;
      }
      if (missing == 0 && !L.on_boundary(v)) runs = 1;
      if (runs <= 1) continue;
      for (Index f : ring)
        if (!taken[size_t(f)]) take(f), changed = true;
    }
  }
  // Vertices of added faces that the labelling did not reach.
  for (Index f : faces)
    for (Index v : L.face(f))
      if (lab.label_of[size_t(v)] == kNone) extra_vertices.push_back(v);
  std::sort(extra_vertices.begin(), extra_vertices.end());
  extra_vertices.erase(std::unique(extra_vertices.begin(), extra_vertices.end()), extra_vertices.end());
  auto keep = [&](Index v) {
    local_of[size_t(v)] = Index(out.original.size());
    scratch.touched_vertices.push_back(v);
    out.original.push_back(v);
  };
  // New vertices in label order, so the centre is vertex 0 (a face centre: its corners first).
  for (size_t q = 0; q < lab.vertices.size(); ++q) {
    const Index v = lab.vertices[q];
    bool used = false;
    for (Index f : L.ring_faces(v))
      if (taken[size_t(f)]) { used = true; break; }
    if (used) keep(v);
  }
  for (Index v : extra_vertices) keep(v);
  std::vector<Index> offsets{0}, corners;
  std::sort(faces.begin(), faces.end());
  for (Index f : faces) {
    for (Index v : L.face(f)) corners.push_back(local_of[size_t(v)]);
    offsets.push_back(Index(corners.size()));
    out.face_original.push_back(f);
  }
  out.level = build_level(Index(out.original.size()), offsets, corners);
  Level& E = out.level;
  if (!L.edge_sharpness.empty()) {
    E.edge_sharpness.assign(size_t(E.edge_count()), 0.f);
    for (Index e = 0; e < E.edge_count(); ++e) {
      const Index a = out.original[size_t(E.edge_vertices[size_t(2 * e)])];
      const Index b = out.original[size_t(E.edge_vertices[size_t(2 * e + 1)])];
      const Index o = find_edge(L, a, b);
      if (o != kNone) E.edge_sharpness[size_t(e)] = L.edge_sharp(o);
    }
  }
  if (!L.vertex_sharpness.empty()) {
    E.vertex_sharpness.assign(size_t(E.vertex_count), 0.f);
    for (Index v = 0; v < E.vertex_count; ++v) E.vertex_sharpness[size_t(v)] = L.vertex_sharp(out.original[size_t(v)]);
  }
  return out;
}

Index Extracted::local(Index v) const {
  const auto it = std::find(original.begin(), original.end(), v);
  return it == original.end() ? kNone : Index(it - original.begin());
}

}  // namespace subdiv
