#include "framework/parameterize/disc_check.h"

#include <algorithm>
#include <fmt/format.h>

#include "framework/topology/non_manifold_place.h"
#include "framework/util/error.h"

namespace subdiv {
namespace {

// Connected components of the vertices, through edges.
int components(const Level& level) {
  std::vector<Index> parent(size_t(level.vertex_count));
  for (Index v = 0; v < level.vertex_count; ++v) parent[size_t(v)] = v;
  auto find = [&](Index v) {
    while (parent[size_t(v)] != v) v = parent[size_t(v)] = parent[size_t(parent[size_t(v)])];
    return v;
  };
  int count = level.vertex_count;
  for (Index e = 0; e < level.edge_count(); ++e) {
    const Index a = find(level.edge_vertices[size_t(2 * e)]), b = find(level.edge_vertices[size_t(2 * e + 1)]);
    if (a != b) parent[size_t(a)] = b, --count;
  }
  return count;
}

// Every boundary loop, each as vertices in the direction its boundary edges are run by
// their faces (slot 0 runs edge_vertices[2e] -> [2e + 1]).
std::vector<std::vector<Index>> boundary_loops(const Level& level) {
  std::vector<Index> next(size_t(level.vertex_count), kNone);
  Index edges = 0;
  for (Index e = 0; e < level.edge_count(); ++e)
    if (level.edge_on_boundary(e)) next[size_t(level.edge_vertices[size_t(2 * e)])] = level.edge_vertices[size_t(2 * e + 1)], ++edges;
  std::vector<std::uint8_t> seen(size_t(level.vertex_count), 0);
  std::vector<std::vector<Index>> loops;
  for (Index v = 0; v < level.vertex_count; ++v) {
    if (next[size_t(v)] == kNone || seen[size_t(v)]) continue;
    std::vector<Index> loop;
    for (Index u = v; !seen[size_t(u)] && u != kNone; u = next[size_t(u)]) seen[size_t(u)] = 1, loop.push_back(u);
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

std::vector<Index> disc_boundary_loop(const Level& level, const std::string& source) {
  if (!level.manifold())
    throw Error(fmt::format("{}: Tutte's embedding needs a topological disc, but the mesh is not manifold: {}",
                            source, non_manifold_place(level)));
  for (Index v = 0; v < level.vertex_count; ++v)
    if (level.incident_face_count(v) == 0)
      throw Error(fmt::format("{}: vertex {} (counted from 0) is on no face; remove unused vertices first", source, v));
  const int parts = components(level);
  if (parts != 1)
    throw Error(fmt::format("{}: the mesh has {} connected parts; a topological disc is one piece (parameterise "
                            "each part on its own)",
                            source, parts));
  const auto loops = boundary_loops(level);
  if (loops.size() != 1)
    throw Error(fmt::format("{}: the mesh has {} boundary loops; a topological disc has exactly one{}", source,
                            loops.size(),
                            loops.empty() ? " (a closed surface must be cut open first)"
                                          : " (fill the holes, or cut the mesh to join them)"));
  const long long chi = (long long)level.vertex_count - level.edge_count() + level.face_count();
  if (chi != 1)
    throw Error(fmt::format("{}: the mesh's Euler characteristic V - E + F is {}, a disc's is 1 (it has handles: "
                            "cut it along a loop through each)",
                            source, chi));
  std::vector<Index> loop = loops.front();
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  return loop;
}

}  // namespace subdiv
