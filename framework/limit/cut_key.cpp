#include "framework/limit/cut_key.h"

#include <algorithm>
#include <cstring>

namespace subdiv {
namespace {

std::uint32_t bits(float x) {
  std::uint32_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// The position of face f in v's ring.
int ring_position(const Level& L, Index v, Index f) {
  const auto faces = L.ring_faces(v);
  for (size_t i = 0; i < faces.size(); ++i)
    if (faces[i] == f) return int(i);
  return 0;
}

}  // namespace

int CutKey::count_within(int d) const {
  return int(std::upper_bound(distance.begin(), distance.end(), d) - distance.begin());
}

void key_cut(CutKey& out, const Level& L, Index face, int radius) {
  for (Index v : out.vertices) out.label_of[size_t(v)] = kNone;
  for (Index f : out.faces) out.face_seen[size_t(f)] = 0;
  if (out.label_of.size() < size_t(L.vertex_count)) out.label_of.resize(size_t(L.vertex_count), kNone);
  if (out.face_seen.size() < size_t(L.face_count())) out.face_seen.resize(size_t(L.face_count()), 0);
  out.vertices.clear(), out.distance.clear(), out.entry.clear(), out.faces.clear(), out.key.clear();
  auto add = [&](Index v, int d, int e) {
    out.label_of[size_t(v)] = Index(out.vertices.size());
    out.vertices.push_back(v);
    out.distance.push_back(d);
    out.entry.push_back(e);
  };
  // label_neighbourhood's breadth-first order: the face's corners from corner 0, then each
  // vertex's faces counter-clockwise from the one it was reached through, each face's
  // corners after the vertex. A face met again has all its corners labelled already, so
  // skipping it changes no label.
  const auto corners = L.face(face);
  for (Index v : corners) add(v, 0, ring_position(L, v, face));
  auto& key = out.key;
  for (size_t q = 0; q < out.vertices.size(); ++q) {
    const Index v = out.vertices[q];
    const int d = out.distance[q];
    key.push_back(std::uint32_t(L.valence(v)));
    key.push_back(std::uint32_t(L.incident_face_count(v)));
    key.push_back(L.on_boundary(v) ? 1u : 0u);
    key.push_back(bits(L.vertex_sharp(v)));
    if (d >= radius) continue;
    const auto faces = L.ring_faces(v);
    const int F = int(faces.size());
    const Index first = L.vertex_face_offsets[v];
    for (int t = 0; t < F; ++t) {
      int fi = out.entry[q] + t;
      if (fi >= F) fi -= F;
      const Index f = faces[size_t(fi)];
      if (out.face_seen[size_t(f)]) continue;
      out.face_seen[size_t(f)] = 1;
      out.faces.push_back(f);
      const int c = L.vertex_face_corner[size_t(first + fi)];
      const auto fc = L.face(f);
      const auto fe = L.face_edge_list(f);
      const int k = int(fc.size());
      key.push_back(std::uint32_t(k));
      key.push_back(L.is_hole(f) ? 1u : 0u);
      for (int i = 0; i < k; ++i) {
        const int at = c + i < k ? c + i : c + i - k;
        const Index w = fc[size_t(at)];
        if (out.label_of[size_t(w)] == kNone) add(w, d + 1, ring_position(L, w, f));
        key.push_back(std::uint32_t(out.label_of[size_t(w)]));
        const Index e = fe[size_t(at)];
        key.push_back(L.edge_on_boundary(e) ? bits(-1.f) : bits(L.edge_sharp(e)));
      }
    }
  }
}

}  // namespace subdiv
