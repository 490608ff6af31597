#pragma once
// OpenSubdiv as a reference for unit tests (header-only; test executables define
// SUBDIV_HAVE_OPENSUBDIV and link OpenSubdiv::osdCPU when Debian's libosd-dev is found).
//
//   #include "support/osd_reference.h"
//   #ifdef SUBDIV_HAVE_OPENSUBDIV
//   subdiv_test::OsdMesh mesh{...};                       // vertex count, face CSR, xyz, tags
//   auto osd = subdiv_test::osd_refine(mesh, {subdiv_test::OsdScheme::CatmullClark}, 2);
//   subdiv::Hierarchy ours = subdiv::refine(*scheme, base, options);
//   auto expected = subdiv_test::osd_in_our_order(osd, ours, 2);   // xyz, our numbering
//   CHECK(subdiv_test::max_abs_difference(expected, our_positions) < 1e-12);
//   #endif
//
// Matching the two libraries' vertices
// ------------------------------------
// The libraries number refined vertices differently. OpenSubdiv (uniform refinement with
// UniformOptions::orderVerticesFromFacesFirst = false, the default used here) numbers the
// children of parent vertices [0, V), then of faces [V, V + F) (none for Loop), then of
// edges, each block in parent order; its edges are numbered by its own factory. SubdivKit
// numbers children of vertices, then of edges, then of faces, with its own edge
// numbering. So the helper matches vertices *by construction*, not by position:
// osd_to_our_order() walks both hierarchies level by level and, for each of our child
// vertices, takes its recorded origin (ChildOrigins) and finds the OpenSubdiv child of the
// same parent component: the same vertex, the edge with the same (mapped) end points
// (TopologyLevel::FindEdge), the face with the same (mapped) corners. A vertex that has
// no counterpart (different topology) is an error, never a silent geometric guess.
//
// Where no SubdivKit hierarchy is at hand (for example positions read back from a file),
// match_points() pairs two point sets by nearest neighbour within a tolerance instead.
#ifdef SUBDIV_HAVE_OPENSUBDIV

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include "framework/engine/refiner.h"

namespace subdiv_test {

enum class OsdScheme { CatmullClark, Loop, Bilinear };
enum class OsdBoundary { None, EdgesOnly, EdgesAndCorners };  // Sdc::Options names
enum class OsdCreasing { Uniform, Chaikin };

struct OsdCrease {
  int v0, v1;
  float sharpness;  // 0 smooth, >= 10 infinitely sharp
};
struct OsdCorner {
  int v;
  float sharpness;
};

struct OsdMesh {
  int vertex_count = 0;
  std::vector<int> face_offsets{0};  // CSR: face f has face_vertices[offsets[f] .. offsets[f+1])
  std::vector<int> face_vertices;
  std::vector<double> xyz;  // 3 per vertex
  std::vector<OsdCrease> creases;
  std::vector<OsdCorner> corners;
  std::vector<int> holes;  // faces tagged as holes
  // One face-varying channel (optional): values (fvar_components each, at most 3) and one
  // value index per face corner.
  int fvar_components = 0;
  std::vector<double> fvar_values;
  std::vector<int> fvar_indices;
};

struct OsdOptions {
  OsdScheme scheme = OsdScheme::CatmullClark;
  OsdBoundary boundary = OsdBoundary::EdgesAndCorners;  // SubdivKit's default
  OsdCreasing creasing = OsdCreasing::Uniform;
  bool smooth_triangles = false;  // Sdc::Options::TRI_SUB_SMOOTH (Catmull-Clark only)
  int fvar_linear = 5;            // Sdc::Options::FVarLinearInterpolation, 0 none .. 5 all (Sdc's default)
};

// Which parent component an OpenSubdiv child vertex came from.
enum class OsdOrigin : std::uint8_t { Vertex, Edge, Face };

struct OsdLevel {
  int vertex_count = 0;
  std::vector<int> face_offsets{0}, face_vertices;  // OpenSubdiv's numbering
  std::vector<int> edge_vertices;                   // 2 per edge
  std::vector<double> xyz;                          // 3 per vertex, OpenSubdiv's order
  std::vector<char> face_hole;                      // per face: TopologyLevel::IsFaceHole
  // Empty at level 0; else per vertex: origin kind and parent index in the level before.
  std::vector<OsdOrigin> origin_kind;
  std::vector<int> origin_parent;
  // The face-varying channel, when the mesh has one: values (3 per value, padded) and
  // per face corner its value, in OpenSubdiv's face order.
  std::vector<double> fvar_values;
  std::vector<int> fvar_corner_values;

  int face_count() const { return int(face_offsets.size()) - 1; }
  int edge_count() const { return int(edge_vertices.size() / 2); }
  std::span<const double> position(int v) const { return {xyz.data() + 3 * size_t(v), 3}; }
};

struct OsdRefinement {
  OsdOptions options;
  std::vector<OsdLevel> levels;  // levels[0] is the base mesh
  std::shared_ptr<const OpenSubdiv::Far::TopologyRefiner> refiner;
};

namespace detail {

struct OsdXyz {
  double p[3];
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const OsdXyz& s, double w) {
    p[0] += w * s.p[0];
    p[1] += w * s.p[1];
    p[2] += w * s.p[2];
  }
};

inline bool quad_split(OsdScheme s) { return s != OsdScheme::Loop; }

// True when OpenSubdiv face `fv` has our corners (through the vertex map): as a set, and
// with `in_order` also in the same cyclic order (the same orientation).
template <class OsdFace>
bool same_corners(std::span<const subdiv::Index> corners, const OsdFace& fv, const std::vector<int>& vmap,
                  bool in_order) {
  const int n = int(corners.size());
  if (fv.size() != n) return false;
  for (int start = 0; start < n && in_order; ++start) {
    bool same = true;
    for (int i = 0; i < n && same; ++i) same = fv[(start + i) % n] == vmap[size_t(corners[size_t(i)])];
    if (same) return true;
  }
  if (in_order) return false;
  for (subdiv::Index v : corners) {
    bool in = false;
    for (int k = 0; k < n; ++k) in = in || fv[k] == vmap[size_t(v)];
    if (!in) return false;
  }
  return true;
}

// For each of our faces, the OpenSubdiv face with the same corners (through the vertex map).
// Faces with the same corners (two faces back to back) are told apart by orientation, and
// each OpenSubdiv face is taken once.
inline std::vector<int> match_faces(const subdiv::Level& ours, const OpenSubdiv::Far::TopologyLevel& osd,
                                    const std::vector<int>& vmap, int level) {
  std::vector<int> fmap(size_t(ours.face_count()));
  std::vector<char> taken(size_t(osd.GetNumFaces()), 0);
  for (subdiv::Index f = 0; f < ours.face_count(); ++f) {
    const auto corners = ours.face(f);
    int found = OpenSubdiv::Far::INDEX_INVALID;
    const auto candidates = osd.GetVertexFaces(vmap[size_t(corners[0])]);
    for (bool in_order : {true, false})
      for (int i = 0; i < candidates.size() && found == OpenSubdiv::Far::INDEX_INVALID; ++i)
        if (!taken[size_t(candidates[i])] && same_corners(corners, osd.GetFaceVertices(candidates[i]), vmap, in_order))
          found = candidates[i];
    if (found == OpenSubdiv::Far::INDEX_INVALID)
      throw std::runtime_error("our_to_osd_vertices: our face " + std::to_string(f) + " has no OpenSubdiv face (level " +
                               std::to_string(level) + ")");
    taken[size_t(found)] = 1;
    fmap[size_t(f)] = found;
  }
  return fmap;
}

// OpenSubdiv's edge for our edge e. Where several edges join the same two vertices (non-
// manifold input: a face that comes back to an edge, an edge from a vertex to itself and its
// halves), the k-th of ours, by index, is paired with the k-th of OpenSubdiv's.
inline int matching_edge(const subdiv::Level& ours, const OpenSubdiv::Far::TopologyLevel& osd,
                         const std::vector<int>& vmap, subdiv::Index e) {
  const subdiv::Index a = ours.edge_vertices[2 * e], b = ours.edge_vertices[2 * e + 1];
  auto joins = [](int x0, int x1, int a0, int b0) { return (x0 == a0 && x1 == b0) || (x0 == b0 && x1 == a0); };
  std::vector<int> candidates;
  const auto edges = osd.GetVertexEdges(vmap[size_t(a)]);
  for (int i = 0; i < edges.size(); ++i) {
    const auto ev = osd.GetEdgeVertices(edges[i]);
    if (joins(ev[0], ev[1], vmap[size_t(a)], vmap[size_t(b)])) candidates.push_back(edges[i]);
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  if (candidates.size() < 2) return candidates.empty() ? OpenSubdiv::Far::INDEX_INVALID : candidates.front();
  int k = 0;  // only where edges repeat: how many of ours join a and b before e
  for (subdiv::Index other = 0; other < e; ++other)
    if (joins(ours.edge_vertices[2 * other], ours.edge_vertices[2 * other + 1], a, b)) ++k;
  return k < int(candidates.size()) ? candidates[size_t(k)] : OpenSubdiv::Far::INDEX_INVALID;
}

}  // namespace detail

// Uniform refinement of `mesh` to `levels` levels with OpenSubdiv's Far (full topology at
// every level) and primvar interpolation of the positions in doubles.
inline OsdRefinement osd_refine(const OsdMesh& mesh, const OsdOptions& options, int levels) {
  using namespace OpenSubdiv;
  if (levels < 0 || levels > 10) throw std::invalid_argument("osd_refine: levels must be in 0..10");
  if (mesh.xyz.size() != 3 * size_t(mesh.vertex_count))
    throw std::invalid_argument("osd_refine: xyz must hold 3 values per vertex");
  const int face_count = int(mesh.face_offsets.size()) - 1;
  std::vector<int> sizes(size_t(std::max(0, face_count)));
  for (int f = 0; f < face_count; ++f) sizes[f] = mesh.face_offsets[f + 1] - mesh.face_offsets[f];
  std::vector<int> crease_pairs;
  std::vector<float> crease_weights;
  for (const auto& c : mesh.creases) {
    crease_pairs.push_back(c.v0);
    crease_pairs.push_back(c.v1);
    crease_weights.push_back(c.sharpness);
  }
  std::vector<int> corner_vertices;
  std::vector<float> corner_weights;
  for (const auto& c : mesh.corners) {
    corner_vertices.push_back(c.v);
    corner_weights.push_back(c.sharpness);
  }

  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.vertex_count;
  desc.numFaces = face_count;
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = mesh.face_vertices.data();
  desc.numCreases = int(crease_weights.size());
  desc.creaseVertexIndexPairs = crease_pairs.data();
  desc.creaseWeights = crease_weights.data();
  desc.numCorners = int(corner_weights.size());
  desc.cornerVertexIndices = corner_vertices.data();
  desc.cornerWeights = corner_weights.data();
  desc.numHoles = int(mesh.holes.size());
  desc.holeIndices = mesh.holes.data();
  Far::TopologyDescriptor::FVarChannel channel;
  if (mesh.fvar_components > 0) {
    channel.numValues = int(mesh.fvar_values.size()) / mesh.fvar_components;
    channel.valueIndices = mesh.fvar_indices.data();
    desc.numFVarChannels = 1;
    desc.fvarChannels = &channel;
  }

  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(options.boundary == OsdBoundary::None        ? Sdc::Options::VTX_BOUNDARY_NONE
                                  : options.boundary == OsdBoundary::EdgesOnly ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                                                               : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  sdc.SetCreasingMethod(options.creasing == OsdCreasing::Chaikin ? Sdc::Options::CREASE_CHAIKIN
                                                                  : Sdc::Options::CREASE_UNIFORM);
  if (options.smooth_triangles) sdc.SetTriangleSubdivision(Sdc::Options::TRI_SUB_SMOOTH);
  sdc.SetFVarLinearInterpolation(Sdc::Options::FVarLinearInterpolation(options.fvar_linear));
  const Sdc::SchemeType type = options.scheme == OsdScheme::Loop       ? Sdc::SCHEME_LOOP
                               : options.scheme == OsdScheme::Bilinear ? Sdc::SCHEME_BILINEAR
                                                                       : Sdc::SCHEME_CATMARK;
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::shared_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(type, sdc)));
  if (!refiner) throw std::runtime_error("osd_refine: OpenSubdiv refused the mesh");
  if (levels > 0) {
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uniform);
  }

  OsdRefinement result;
  result.options = options;
  result.levels.resize(size_t(levels) + 1);
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  for (int l = 0; l <= levels; ++l) {
    const auto& tl = refiner->GetLevel(l);
    OsdLevel& out = result.levels[size_t(l)];
    out.vertex_count = tl.GetNumVertices();
    for (int f = 0; f < tl.GetNumFaces(); ++f) {
      out.face_hole.push_back(char(tl.IsFaceHole(f)));
      auto fv = tl.GetFaceVertices(f);
      for (int i = 0; i < fv.size(); ++i) out.face_vertices.push_back(fv[i]);
      out.face_offsets.push_back(int(out.face_vertices.size()));
    }
    for (int e = 0; e < tl.GetNumEdges(); ++e) {
      auto ev = tl.GetEdgeVertices(e);
      out.edge_vertices.push_back(ev[0]);
      out.edge_vertices.push_back(ev[1]);
    }
    out.xyz.resize(3 * size_t(out.vertex_count));
    if (mesh.fvar_components > 0) {
      for (int f = 0; f < tl.GetNumFaces(); ++f) {
        const auto fv = tl.GetFaceFVarValues(f, 0);
        for (int i = 0; i < fv.size(); ++i) out.fvar_corner_values.push_back(fv[i]);
      }
      out.fvar_values.assign(3 * size_t(tl.GetNumFVarValues(0)), 0.0);
      if (l == 0) {
        for (size_t i = 0; i < mesh.fvar_values.size(); ++i)
          out.fvar_values[3 * (i / mesh.fvar_components) + i % mesh.fvar_components] = mesh.fvar_values[i];
      } else {
        const auto* from = reinterpret_cast<const detail::OsdXyz*>(result.levels[size_t(l) - 1].fvar_values.data());
        auto* to = reinterpret_cast<detail::OsdXyz*>(out.fvar_values.data());
        primvar.InterpolateFaceVarying(l, from, to, 0);
      }
    }
    if (l == 0) {
      out.xyz = mesh.xyz;
      continue;
    }
    const auto& src = result.levels[size_t(l) - 1];
    const auto* from = reinterpret_cast<const detail::OsdXyz*>(src.xyz.data());
    auto* to = reinterpret_cast<detail::OsdXyz*>(out.xyz.data());
    primvar.Interpolate(l, from, to);
    // Child numbering of a uniform refinement (orderVerticesFromFacesFirst = false).
    const int V = src.vertex_count, F = detail::quad_split(options.scheme) ? src.face_count() : 0,
              E = src.edge_count();
    if (out.vertex_count != V + F + E)
      throw std::runtime_error("osd_refine: unexpected child vertex count at level " + std::to_string(l));
    out.origin_kind.resize(size_t(out.vertex_count));
    out.origin_parent.resize(size_t(out.vertex_count));
    for (int c = 0; c < out.vertex_count; ++c) {
      if (c < V) {
        out.origin_kind[c] = OsdOrigin::Vertex;
        out.origin_parent[c] = c;
      } else if (c < V + F) {
        out.origin_kind[c] = OsdOrigin::Face;
        out.origin_parent[c] = c - V;
      } else {
        out.origin_kind[c] = OsdOrigin::Edge;
        out.origin_parent[c] = c - V - F;
      }
    }
  }
  result.refiner = std::move(refiner);
  return result;
}

// For each of our vertices at `level`, the index of the same vertex in OpenSubdiv's
// level (see the header comment). Throws std::runtime_error naming the first vertex or
// face without a counterpart.
inline std::vector<int> our_to_osd_vertices(const OsdRefinement& osd, const subdiv::Hierarchy& ours, int level) {
  using OpenSubdiv::Far::INDEX_INVALID;
  if (level < 0 || size_t(level) >= osd.levels.size() || size_t(level) >= ours.levels.size())
    throw std::invalid_argument("our_to_osd_vertices: level " + std::to_string(level) + " not refined on both sides");
  if (ours.levels[0].vertex_count != osd.levels[0].vertex_count ||
      ours.levels[0].face_count() != osd.levels[0].face_count())
    throw std::runtime_error("our_to_osd_vertices: the base meshes differ");
  // Base vertices are the same on both sides; faces are matched by corners like all others.
  std::vector<int> vmap(size_t(ours.levels[0].vertex_count));
  std::iota(vmap.begin(), vmap.end(), 0);
  std::vector<int> fmap = detail::match_faces(ours.levels[0], osd.refiner->GetLevel(0), vmap, 0);
  for (int l = 0; l < level; ++l) {
    const subdiv::Level& parent = ours.levels[size_t(l)];
    const subdiv::Level& child = ours.levels[size_t(l) + 1];
    const subdiv::ChildOrigins& origins = ours.origins[size_t(l)];
    const auto& op = osd.refiner->GetLevel(l);
    const auto& oc = osd.refiner->GetLevel(l + 1);
    const std::string at = " (level " + std::to_string(l + 1) + ")";
    if (child.vertex_count != oc.GetNumVertices() || child.face_count() != oc.GetNumFaces())
      throw std::runtime_error("our_to_osd_vertices: vertex or face counts differ" + at);
    const int V = op.GetNumVertices(), F = detail::quad_split(osd.options.scheme) ? op.GetNumFaces() : 0;
    std::vector<int> next(size_t(child.vertex_count));
    for (subdiv::Index c = 0; c < child.vertex_count; ++c) {
      const subdiv::Index p = origins.parent[size_t(c)];
      switch (origins.kind[size_t(c)]) {
        case subdiv::OriginKind::Vertex: next[c] = vmap[p]; break;
        case subdiv::OriginKind::Edge: {
          const int e = detail::matching_edge(parent, op, vmap, p);
          if (e == INDEX_INVALID)
            throw std::runtime_error("our_to_osd_vertices: our edge " + std::to_string(p) + " has no OpenSubdiv edge" + at);
          next[c] = V + F + e;
          break;
        }
        case subdiv::OriginKind::Face:
          if (F == 0) throw std::runtime_error("our_to_osd_vertices: a face child in a triangle split" + at);
          next[c] = V + fmap[p];
          break;
        default: throw std::runtime_error("our_to_osd_vertices: face-corner children have no OpenSubdiv counterpart");
      }
    }
    std::vector<char> hit(next.size(), 0);
    for (int o : next) {
      if (hit[size_t(o)]) throw std::runtime_error("our_to_osd_vertices: two of our vertices map to one" + at);
      hit[size_t(o)] = 1;
    }
    fmap = detail::match_faces(child, oc, next, l + 1);
    vmap = std::move(next);
  }
  return vmap;
}

// OpenSubdiv's positions at `level` in our vertex order.
inline std::vector<double> osd_in_our_order(const OsdRefinement& osd, const subdiv::Hierarchy& ours, int level) {
  const auto map = our_to_osd_vertices(osd, ours, level);
  const auto& src = osd.levels[size_t(level)].xyz;
  std::vector<double> out(3 * map.size());
  for (size_t v = 0; v < map.size(); ++v)
    for (int c = 0; c < 3; ++c) out[3 * v + c] = src[3 * size_t(map[v]) + c];
  return out;
}

// Largest |a_i - b_i|; infinity when the sizes differ or a value is NaN.
// The vertex (xyz triples) where a and b differ most, and by how much; a NaN counts as an
// infinite difference.
struct WorstVertex {
  double difference = 0;
  size_t vertex = 0;
};
inline WorstVertex worst_vertex(std::span<const double> a, std::span<const double> b) {
  WorstVertex w;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (double d = std::abs(a[i] - b[i]); !(d <= w.difference))
      w.difference = std::isnan(d) ? INFINITY : d, w.vertex = i / 3;
  return w;
}

// The largest difference between our face-varying values and OpenSubdiv's at any face
// corner of levels 1..levels. `values[l]` and `corner_values[l]` are ours at level l
// (`components` per value, one index per corner of ours.levels[l]); faces are paired by
// their corners through our_to_osd_vertices.
inline double max_face_varying_difference(const OsdRefinement& osd, const subdiv::Hierarchy& ours,
                                          const std::vector<std::vector<double>>& values,
                                          const std::vector<std::vector<subdiv::Index>>& corner_values,
                                          int components, int levels) {
  double worst = 0;
  for (int l = 1; l <= levels; ++l) {
    const auto vmap = our_to_osd_vertices(osd, ours, l);
    const auto& tl = osd.refiner->GetLevel(l);
    const subdiv::Level& L = ours.levels[size_t(l)];
    const auto fmap = detail::match_faces(L, tl, vmap, l);
    const OsdLevel& far = osd.levels[size_t(l)];
    for (subdiv::Index f = 0; f < L.face_count(); ++f) {
      const auto fv = tl.GetFaceVertices(fmap[size_t(f)]);
      for (int k = 0; k < L.face_size(f); ++k) {
        int j = 0;
        while (fv[j] != vmap[size_t(L.face(f)[k])]) ++j;
        const int theirs = far.fvar_corner_values[size_t(far.face_offsets[size_t(fmap[size_t(f)])] + j)];
        const subdiv::Index mine = corner_values[size_t(l)][size_t(L.face_offsets[f] + k)];
        for (int c = 0; c < components; ++c)
          worst = std::max(worst, std::abs(values[size_t(l)][size_t(mine) * components + c] -
                                           far.fvar_values[3 * size_t(theirs) + c]));
      }
    }
  }
  return worst;
}

inline double max_abs_difference(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
  double m = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double d = std::abs(a[i] - b[i]);
    if (!(d <= m)) m = std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
  }
  return m;
}

// Order-free comparison of two xyz point sets: every point of `a` is paired with a
// distinct point of `b` whose coordinates all differ by at most `tolerance`.
struct PointMatch {
  bool ok = false;
  int unmatched = 0;          // points of a without a partner
  double max_difference = 0;  // largest coordinate difference over the pairs found
  std::vector<int> a_to_b;    // partner index in b, or -1
};

inline PointMatch match_points(std::span<const double> a, std::span<const double> b, double tolerance) {
  PointMatch m;
  const size_t na = a.size() / 3, nb = b.size() / 3;
  m.a_to_b.assign(na, -1);
  std::vector<int> order(nb);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) { return b[3 * size_t(i)] < b[3 * size_t(j)]; });
  std::vector<char> used(nb, 0);
  for (size_t i = 0; i < na; ++i) {
    const double x = a[3 * i];
    auto lo = std::lower_bound(order.begin(), order.end(), x - tolerance,
                               [&](int j, double value) { return b[3 * size_t(j)] < value; });
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (auto it = lo; it != order.end() && b[3 * size_t(*it)] <= x + tolerance; ++it) {
      if (used[size_t(*it)]) continue;
      double d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a[3 * i + c] - b[3 * size_t(*it) + c]));
      if (d <= tolerance && d < best_d) best = *it, best_d = d;
    }
    if (best < 0) {
      ++m.unmatched;
      continue;
    }
    used[size_t(best)] = 1;
    m.a_to_b[i] = best;
    m.max_difference = std::max(m.max_difference, best_d);
  }
  m.ok = na == nb && m.unmatched == 0;
  return m;
}

}  // namespace subdiv_test

#endif  // SUBDIV_HAVE_OPENSUBDIV
