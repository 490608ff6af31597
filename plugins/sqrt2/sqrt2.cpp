// A new topology rule: the sqrt(2) split, and a scheme in the JSON language that uses it.
//
// The split (the topology of G. Li, W. Ma, H. Bao, "sqrt(2) subdivision for quadrilateral
// meshes", The Visual Computer 20 (2004), and of the 4-8 refinement of L. Velho, D. Zorin,
// "4-8 subdivision", CAGD 18 (2001)): every face gets a new face point; every interior edge
// (a, b) between faces f and g is replaced by the quad (a, face point of g, b, face point
// of f), so old edges are "flipped" and a quad mesh stays a quad mesh with twice the faces,
// rotated by 45 degrees. A boundary edge gets a new edge point e and gives the triangles
// (a, e, face point) and (e, b, face point), so boundaries are refined like binary curves;
// at a boundary corner (a vertex in one face) the two triangles are one quad, so the corner
// keeps valence 2 and stays a corner.
// Works on any polygons. Crease tags on interior edges cannot follow (those edges are
// gone); vertex sharpness is carried to the old vertices, one level less.
//
// The scheme "sqrt2" (JSON, in this file): face point = centroid of the face; old vertex
// v' = v/2 + (mean of its new face points)/2; boundaries follow the cubic B-spline. On a
// regular quad grid two steps make one dyadic refinement.
#include "framework/plugin/plugin_api.h"
#include "framework/refine/child_tags.h"
#include "framework/util/error.h"

#include <cmath>

namespace {

using subdiv::Index;
using subdiv::kNone;

subdiv::SplitResult split_sqrt2(const subdiv::Level& parent, int) {
  const Index V = parent.vertex_count, E = parent.edge_count(), F = parent.face_count();
  subdiv::SplitResult result;
  subdiv::ChildOrigins& o = result.origins;
  // Child vertices in blocks: old vertices, boundary edge points, face points.
  std::vector<Index> edge_point(E, kNone);
  Index next = V;
  for (Index e = 0; e < E; ++e)
    if (parent.edge_on_boundary(e)) edge_point[e] = next++;
  const Index first_face_point = next;
  const Index child_count = first_face_point + F;
  o.kind.resize(child_count);
  o.parent.resize(child_count);
  o.local.assign(child_count, 0);
  for (Index v = 0; v < V; ++v) o.kind[v] = subdiv::OriginKind::Vertex, o.parent[v] = v;
  for (Index e = 0; e < E; ++e)
    if (edge_point[e] != kNone) o.kind[edge_point[e]] = subdiv::OriginKind::Edge, o.parent[edge_point[e]] = e;
  for (Index f = 0; f < F; ++f) o.kind[first_face_point + f] = subdiv::OriginKind::Face, o.parent[first_face_point + f] = f;

  std::vector<Index> offsets{0}, corners;
  auto add_face = [&](std::initializer_list<Index> face, Index parent_face) {
    corners.insert(corners.end(), face);
    offsets.push_back(Index(corners.size()));
    o.parent_face.push_back(parent_face);
  };
  // A boundary vertex in one face only (a corner of the boundary) gets one quad instead of
  // two triangles, so it keeps valence 2 and stays a corner.
  auto corner_vertex = [&](Index v) { return parent.on_boundary(v) && parent.incident_face_count(v) == 1; };
  for (Index e = 0; e < E; ++e) {
    const Index a = parent.edge_vertices[2 * e], b = parent.edge_vertices[2 * e + 1];
    const Index f = parent.edge_faces[2 * e], g = parent.edge_faces[2 * e + 1];  // f runs a -> b
    if (g == kNone) {
      if (!corner_vertex(a)) add_face({a, edge_point[e], first_face_point + f}, f);
      if (!corner_vertex(b)) add_face({edge_point[e], b, first_face_point + f}, f);
    } else {
      add_face({a, first_face_point + g, b, first_face_point + f}, kNone);
    }
  }
  for (Index v = 0; v < V; ++v) {
    if (!corner_vertex(v)) continue;
    const Index f = parent.ring_faces(v)[0];
    const int k = parent.face_size(f);
    const int c = parent.vertex_face_corner[parent.vertex_face_offsets[v]];
    const Index out = parent.face_edge_list(f)[c], in = parent.face_edge_list(f)[(c + k - 1) % k];
    add_face({edge_point[in], v, edge_point[out], first_face_point + f}, f);
  }
  result.child = subdiv::build_level(child_count, offsets, corners);
  if (!parent.vertex_sharpness.empty()) {
    result.child.vertex_sharpness.assign(child_count, 0.f);
    for (Index v = 0; v < V; ++v) result.child.vertex_sharpness[v] = subdiv::decremented_sharpness(parent.vertex_sharpness[v]);
  }
  return result;
}

constexpr const char* kSqrt2Scheme = R"json({
  "name": "sqrt2",
  "description": "sqrt(2) / 4-8 subdivision on the sqrt2 split: face centroids, old vertices halfway to the mean of their new face points",
  "reference": "topology: Li, Ma, Bao 2004 (sqrt(2) subdivision for quad meshes); Velho, Zorin 2001 (4-8 subdivision)",
  "split": "sqrt2",
  "curve": "cubic-bspline",
  "rules": {
    "face": [{"sum": "vertices", "w": "1/k"}],
    "vertex": [{"at": "self", "w": "1/2"}, {"sum": "faces", "new": "face", "w": "1/(2*n)"}],
    "edge": [{"sum": "ends", "w": "1/2"}]
  }
})json";

void register_sqrt2(subdiv::PluginRegistry& registry) {
  subdiv::SplitterInfo split;
  split.name = "sqrt2";
  split.description = "sqrt(2) split: face points, interior edges flipped into quads, boundary edges halved";
  split.split = split_sqrt2;
  split.rule_elements = {subdiv::OriginKind::Vertex, subdiv::OriginKind::Edge, subdiv::OriginKind::Face};
  split.curve_arity = 2;
  split.primal = true;
  // Each step shrinks the grid by sqrt 2 and turns it by 45 degrees; two steps are one
  // dyadic refinement, so the analysis studies S^2 at scale 2.
  split.scale = std::sqrt(2.0);
  split.period = 2;
  registry.add_splitter(std::move(split));
  registry.add_json_scheme(kSqrt2Scheme);
}

}  // namespace

SUBDIV_PLUGIN("sqrt2", "1.0.0", register_sqrt2)
