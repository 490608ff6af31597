#include "framework/limit/adaptive_transitions.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace subdiv {
namespace {

// A new face as positions among its polygon's corners, in the polygon's orientation.
using Face = std::vector<size_t>;

// The polygon's own corners (`corner`: positions among its corners) and per side (from corner
// i to i + 1) the finer vertices along it.
struct Sides {
  std::vector<size_t> corner;
  std::vector<std::vector<size_t>> along;
};

Sides sides_of(std::span<const std::uint8_t> is_corner) {
  Sides s;
  for (size_t k = 0; k < is_corner.size(); ++k)
    if (is_corner[k]) s.corner.push_back(k);
  s.along.resize(s.corner.size());
  for (size_t i = 0; i < s.corner.size(); ++i)
    for (size_t k = s.corner[i] + 1; k < (i + 1 < s.corner.size() ? s.corner[i + 1] : is_corner.size()); ++k)
      s.along[i].push_back(k);
  return s;
}

// The fixed patterns, for a quad or triangle with at most one finer vertex per side: c(i) is
// corner i, m(i) the finer vertex of side i (from corner i to i + 1), indices mod n, rotated
// so that r is the first split side of the pattern. All faces keep the polygon's orientation.
// On a quad, 1 split side: the midpoint joined to the opposite corners; 2 adjacent: a fan from
// the corner opposite their common corner; 2 opposite: two quads; 3: the half along the side
// not split a quad, the other half three triangles (OpenSubdiv 2's patterns 0, 1, 4 and 2).
std::vector<Face> pattern(const Sides& s) {
  const size_t n = s.corner.size();
  std::vector<bool> split(n);
  for (size_t i = 0; i < n; ++i) split[i] = !s.along[i].empty();
  const size_t count = size_t(std::count(split.begin(), split.end(), true));
  // r: a split side whose previous side is not split (for 2 opposite: either split side).
  size_t r = 0;
  for (size_t i = 0; i < n; ++i)
    if (split[i] && (count == n || !split[(i + n - 1) % n])) {
      r = i;
      break;
    }
  auto c = [&](size_t i) { return s.corner[(r + i) % n]; };
  auto m = [&](size_t i) { return s.along[(r + i) % n].front(); };
  auto is_split = [&](size_t i) { return split[(r + i) % n]; };
  if (n == 3) {
    if (count == 1) return {{c(0), m(0), c(2)}, {m(0), c(1), c(2)}};
    if (count == 2) return {{m(0), c(1), m(1)}, {c(0), m(0), m(1), c(2)}};
    return {{c(0), m(0), m(2)}, {m(0), c(1), m(1)}, {m(2), m(1), c(2)}, {m(0), m(1), m(2)}};
  }
  if (count == 1) return {{c(0), m(0), c(3)}, {m(0), c(1), c(2)}, {m(0), c(2), c(3)}};
  if (count == 2 && is_split(2)) return {{c(0), m(0), m(2), c(3)}, {m(0), c(1), c(2), m(2)}};
  if (count == 2)  // sides 0 and 1: a fan from the corner opposite the split ones' common corner
    return {{m(0), c(1), m(1)}, {c(0), m(0), c(3)}, {m(0), m(1), c(3)}, {m(1), c(2), c(3)}};
  if (count == 3)
    return {{m(0), c(1), m(1)}, {m(1), c(2), m(2)}, {m(0), m(1), m(2)}, {c(0), m(0), m(2), c(3)}};
  return {{m(3), c(0), m(0)}, {m(0), c(1), m(1)}, {m(1), c(2), m(2)}, {m(2), c(3), m(3)}, {m(0), m(1), m(2), m(3)}};
}

// Any convex polygon with finer vertices along its sides: its boundary cut at corners r and
// r + n/2 into chain a (forward) and chain b (backward), then triangles zipped between them.
// Each triangle has corners on both chains' insides (or the chains' ends between two sides
// meeting there), so no three of its corners lie on one side: none is degenerate. Both
// insides must hold a vertex: on a triangle (chain a one side) r is a side with finer vertices.
std::vector<Face> zipped(const Sides& s) {
  const size_t n = s.corner.size();
  size_t r = 0;
  if (n == 3)
    while (s.along[r].empty()) ++r;
  const size_t h = n / 2;
  std::vector<size_t> a, b;
  for (size_t i = 0; i < h; ++i) {
    a.push_back(s.corner[(r + i) % n]);
    a.insert(a.end(), s.along[(r + i) % n].begin(), s.along[(r + i) % n].end());
  }
  a.push_back(s.corner[(r + h) % n]);
  for (size_t i = n; i > h; --i) {
    const size_t side = (r + i - 1) % n;
    b.push_back(s.corner[(side + 1) % n]);
    b.insert(b.end(), s.along[side].rbegin(), s.along[side].rend());
  }
  b.push_back(s.corner[(r + h) % n]);
  const size_t p = a.size() - 1, q = b.size() - 1;
  std::vector<Face> faces{{a[0], a[1], b[1]}};
  size_t i = 1, j = 1;
  while (i < p - 1 || j < q - 1) {
    // Advance the chain that is behind (by the fraction of it walked), for even triangles.
    const bool advance_a = j == q - 1 || (i < p - 1 && double(i + 1) * double(q) <= double(j + 1) * double(p));
    if (advance_a) faces.push_back({b[j], a[i], a[i + 1]}), ++i;
    else faces.push_back({a[i], b[j + 1], b[j]}), ++j;
  }
  faces.push_back({a[p - 1], a[p], b[q - 1]});
  return faces;
}

}  // namespace

void tessellate_transitions(AdaptiveMesh& m) {
  std::vector<Index> offsets{0}, vertices;
  std::vector<int> level;
  std::vector<Index> base;
  std::vector<std::array<double, 2>> uv;
  std::vector<std::uint8_t> is_corner;
  std::vector<std::vector<Index>> values(m.face_varying.size());
  for (size_t f = 0; f + 1 < m.face_offsets.size(); ++f) {
    const size_t first = size_t(m.face_offsets[f]), size = size_t(m.face_offsets[f + 1]) - first;
    const std::span<const std::uint8_t> flags(m.corner_is_face_corner.data() + first, size);
    std::vector<Face> faces;
    const Sides s = sides_of(flags);
    const bool transition = s.corner.size() < size;
    if (!transition) {
      faces.emplace_back(size);
      for (size_t k = 0; k < size; ++k) faces.back()[k] = k;
    } else {
      bool single = s.corner.size() == 3 || s.corner.size() == 4;
      for (const auto& along : s.along) single = single && along.size() <= 1;
      faces = single ? pattern(s) : zipped(s);
    }
    for (const Face& face : faces) {
      for (size_t k : face) {
        vertices.push_back(m.face_vertices[first + k]);
        uv.push_back(m.corner_uv[first + k]);
        is_corner.push_back(m.corner_is_face_corner[first + k]);
        for (size_t c = 0; c < values.size(); ++c) values[c].push_back(m.face_varying[c].indices[first + k]);
      }
      offsets.push_back(Index(vertices.size()));
      level.push_back(m.face_level[f]);
      base.push_back(m.base_face[f]);
    }
  }
  m.face_offsets = std::move(offsets);
  m.face_vertices = std::move(vertices);
  m.face_level = std::move(level);
  m.base_face = std::move(base);
  m.corner_uv = std::move(uv);
  m.corner_is_face_corner = std::move(is_corner);
  for (size_t c = 0; c < values.size(); ++c) m.face_varying[c].indices = std::move(values[c]);
}

}  // namespace subdiv
