#include "framework/topology/non_manifold_place.h"

#include <algorithm>
#include <span>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace subdiv {
namespace {

// A list of faces, cut after a few: a vertex of a large fan has hundreds.
std::string face_list(std::span<const Index> faces) {
  constexpr std::size_t kShown = 6;
  if (faces.size() <= kShown) return fmt::format("{}", fmt::join(faces, ", "));
  return fmt::format("{}, ... {} in all", fmt::join(faces.first(kShown), ", "), faces.size());
}

// How many of face f's sides join a and b, either way round.
int sides_on(const Level& level, Index f, Index a, Index b) {
  const std::span<const Index> corners = level.face(f);
  int sides = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Index u = corners[i], w = corners[(i + 1) % corners.size()];
    sides += (u == a && w == b) || (u == b && w == a);
  }
  return sides;
}

// Whether face f runs from a to b (a then b, cyclically) at some corner.
bool runs(const Level& level, Index f, Index a, Index b) {
  const std::span<const Index> corners = level.face(f);
  for (std::size_t i = 0; i < corners.size(); ++i)
    if (corners[i] == a && corners[(i + 1) % corners.size()] == b) return true;
  return false;
}

// Where, and how to repair it.
struct Place {
  std::string where, fix;
};

// Whether faces f and g have the same corners (in any order): a face written twice.
bool same_corners(const Level& level, Index f, Index g) {
  std::vector<Index> a(level.face(f).begin(), level.face(f).end()), b(level.face(g).begin(), level.face(g).end());
  std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
  return a == b;
}

Place edge_place(const Level& level, Index e) {
  const Index a = level.edge_vertices[2 * e], b = level.edge_vertices[2 * e + 1];
  const std::span<const Index> faces = level.faces_of_edge(e);
  if (a == b)
    return {fmt::format("face {} repeats vertex {} (its edge {}-{} joins the vertex to itself)",
                        faces.empty() ? kNone : faces[0], a, a, b),
            "remove the repeat from the face"};
  for (const Index f : faces)
    if (sides_on(level, f, a, b) > 1)
      return {fmt::format("face {} runs edge {}-{} twice (it comes back to a vertex)", f, a, b),
              "remove the repeat from the face"};
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (same_corners(level, faces[j], faces[i]))
        return {fmt::format("faces {} and {} have the same corners (a face written twice)", faces[j], faces[i]),
                "remove one of them"};
  if (faces.size() > 2)
    return {fmt::format("edge {}-{} has {} faces ({}), where a manifold edge has one or two", a, b, faces.size(),
                        face_list(faces)),
            "split the mesh along it"};
  if (faces.size() == 2 && runs(level, faces[0], a, b) == runs(level, faces[1], a, b))
    return {fmt::format("faces {} and {} run edge {}-{} in the same direction (their orientations disagree)",
                        faces[0], faces[1], a, b),
            "flip one of them so that the mesh is consistently oriented"};
  return {fmt::format("edge {}-{} (faces {}) is not manifold", a, b, face_list(faces)), "split the mesh there"};
}

Place vertex_place(const Level& level, Index v) {
  std::vector<Index> faces(level.ring_faces(v).begin(), level.ring_faces(v).end());
  std::sort(faces.begin(), faces.end());
  return {fmt::format("the faces around vertex {} ({}) meet only at the vertex, in separate fans", v,
                      face_list(faces)),
          "give each fan its own copy of the vertex"};
}

}  // namespace

std::string non_manifold_place(const Level& level) {
  if (level.manifold()) return {};
  const auto said = [](const Place& p) { return fmt::format("{} (faces and vertices counted from 0); {}", p.where, p.fix); };
  for (Index e = 0; e < level.edge_count(); ++e)
    if (level.non_manifold_edge(e)) return said(edge_place(level, e));
  for (Index v = 0; v < level.vertex_count; ++v)
    if (level.non_manifold_vertex(v)) return said(vertex_place(level, v));
  return "no non-manifold element is marked";
}

}  // namespace subdiv
