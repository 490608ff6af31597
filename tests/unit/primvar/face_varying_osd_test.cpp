// Face-varying data against OpenSubdiv's Far (PrimvarRefiner::InterpolateFaceVarying): UVs
// with seams, darts, corners, boundaries and creases, every linear-interpolation mode,
// Catmull-Clark and Loop, both corner rules of the vertex boundary, levels 1-3: every face
// corner's value equal to Far's to 1e-12.
#include <doctest/doctest.h>

#include <map>
#include <tuple>

#include "framework/primvar/face_varying.h"
#include "framework/scheme/scheme_registry.h"
#include "support/osd_reference.h"
#include "support/test_meshes.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV
using namespace subdiv;
using namespace subdiv::test;
using namespace subdiv_test;

namespace {

struct Uv {
  double p[2];
  void Clear(void* = nullptr) { p[0] = p[1] = 0; }
  void AddWithWeight(const Uv& s, double w) { p[0] += w * s.p[0], p[1] += w * s.p[1]; }
};

// A mesh with a face-varying channel: 2 values per entry, one index per face corner.
struct UvMesh {
  Mesh mesh;
  std::vector<double> uv;
  std::vector<Index> indices;
  std::vector<OsdCrease> creases;
};

// Per level, per OpenSubdiv face, its corners' values.
struct FarUv {
  OsdRefinement vertices;
  std::vector<std::vector<double>> values;      // per level: 2 per value
  std::vector<std::vector<int>> face_values;    // per level: per face corner, OpenSubdiv's face order
};

OpenSubdiv::Sdc::Options::FVarLinearInterpolation far_mode(FaceVaryingLinear m) {
  using O = OpenSubdiv::Sdc::Options;
  const O::FVarLinearInterpolation modes[] = {O::FVAR_LINEAR_NONE,          O::FVAR_LINEAR_CORNERS_ONLY,
                                              O::FVAR_LINEAR_CORNERS_PLUS1, O::FVAR_LINEAR_CORNERS_PLUS2,
                                              O::FVAR_LINEAR_BOUNDARIES,    O::FVAR_LINEAR_ALL};
  return modes[int(m)];
}

FarUv far_refine(const UvMesh& m, const OsdOptions& options, FaceVaryingLinear mode, int levels) {
  using namespace OpenSubdiv;
  OsdMesh om;
  om.vertex_count = m.mesh.vertex_count;
  om.face_offsets.assign(m.mesh.offsets.begin(), m.mesh.offsets.end());
  om.face_vertices.assign(m.mesh.corners.begin(), m.mesh.corners.end());
  om.xyz = m.mesh.positions;
  om.creases = m.creases;
  FarUv out;
  out.vertices = osd_refine(om, options, levels);
  // The same topology again, with the channel.
  std::vector<int> sizes;
  for (size_t f = 0; f + 1 < om.face_offsets.size(); ++f) sizes.push_back(om.face_offsets[f + 1] - om.face_offsets[f]);
  std::vector<int> pairs, indices(m.indices.begin(), m.indices.end());
  std::vector<float> weights;
  for (const auto& c : m.creases) pairs.push_back(c.v0), pairs.push_back(c.v1), weights.push_back(c.sharpness);
  Far::TopologyDescriptor desc;
  desc.numVertices = om.vertex_count;
  desc.numFaces = int(sizes.size());
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = om.face_vertices.data();
  desc.numCreases = int(weights.size());
  desc.creaseVertexIndexPairs = pairs.data();
  desc.creaseWeights = weights.data();
  Far::TopologyDescriptor::FVarChannel channel;
  channel.numValues = int(m.uv.size() / 2);
  channel.valueIndices = indices.data();
  desc.numFVarChannels = 1;
  desc.fvarChannels = &channel;
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(options.boundary == OsdBoundary::EdgesOnly ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                                                             : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  sdc.SetFVarLinearInterpolation(far_mode(mode));
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(
      desc, Factory::Options(options.scheme == OsdScheme::Loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, sdc)));
  REQUIRE(refiner);
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  out.values.push_back(m.uv);
  for (int l = 0; l <= levels; ++l) {
    const auto& tl = refiner->GetLevel(l);
    if (l > 0) {
      out.values.emplace_back(size_t(tl.GetNumFVarValues(0)) * 2);
      const Uv* from = reinterpret_cast<const Uv*>(out.values[size_t(l) - 1].data());
      Uv* to = reinterpret_cast<Uv*>(out.values[size_t(l)].data());
      primvar.InterpolateFaceVarying(l, from, to, 0);
    }
    std::vector<int> corners;
    for (int f = 0; f < tl.GetNumFaces(); ++f) {
      const auto fv = tl.GetFaceFVarValues(f, 0);
      for (int k = 0; k < fv.size(); ++k) corners.push_back(fv[k]);
    }
    out.face_values.push_back(std::move(corners));
  }
  return out;
}

// The worst difference between our corner values and Far's, per level.
double worst_difference(const UvMesh& m, const std::string& scheme_name, const OsdOptions& o, FaceVaryingLinear mode,
                        int levels) {
  const auto scheme = load_scheme(scheme_name);
  const SchemeRun run{scheme.get(), levels};
  RefineOptions ro;
  ro.features.boundary = o.boundary == OsdBoundary::EdgesOnly ? BoundaryInterpolation::EdgesOnly
                                                              : BoundaryInterpolation::EdgesAndCorners;
  Level base = m.mesh.level();
  for (const auto& c : m.creases) {
    base.edge_sharpness.resize(size_t(base.edge_count()), 0.f);
    base.edge_sharpness[find_edge(base, c.v0, c.v1)] = c.sharpness;
  }
  const Hierarchy h = refine_topology(std::span(&run, 1), base, ro);
  const auto ours = refine_face_varying(std::span(&run, 1), h, {m.uv, m.indices}, 2, mode, ro);
  const FarUv far = far_refine(m, o, mode, levels);
  double worst = 0;
  for (int l = 1; l <= levels; ++l) {
    const auto vmap = our_to_osd_vertices(far.vertices, h, l);
    const auto& tl = far.vertices.refiner->GetLevel(l);
    const auto fmap = subdiv_test::detail::match_faces(h.levels[l], tl, vmap, l);
    const Level& L = h.levels[l];
    std::vector<int> far_offsets{0};
    for (int f = 0; f < tl.GetNumFaces(); ++f) far_offsets.push_back(far_offsets.back() + tl.GetFaceVertices(f).size());
    for (Index f = 0; f < L.face_count(); ++f) {
      const auto fv = tl.GetFaceVertices(fmap[f]);
      for (int k = 0; k < L.face_size(f); ++k) {
        int j = 0;
        while (fv[j] != vmap[L.face(f)[k]]) ++j;
        const int far_value = far.face_values[size_t(l)][size_t(far_offsets[fmap[f]] + j)];
        const Index our_value = ours[size_t(l)].indices[size_t(L.face_offsets[f] + k)];
        for (int c = 0; c < 2; ++c)
          worst = std::max(worst, std::abs(ours[size_t(l)].values[2 * size_t(our_value) + c] -
                                           far.values[size_t(l)][2 * size_t(far_value) + c]));
      }
    }
  }
  return worst;
}

// An nx x ny grid whose UVs are cut along the column x = cut (a seam from boundary to
// boundary) and, with `dart`, along half of the row y = 1 from the left (a seam that ends
// inside the mesh).
UvMesh seamed_grid(int nx, int ny, int cut, bool dart, bool triangles) {
  UvMesh m{grid(nx, ny, triangles), {}, {}, {}};
  const Level L = m.mesh.level();
  std::map<std::tuple<Index, int, int>, Index> value_of;
  for (Index f = 0; f < L.face_count(); ++f) {
    double cx = 0, cy = 0;
    for (Index v : L.face(f)) cx += m.mesh.positions[3 * v], cy += m.mesh.positions[3 * v + 1];
    cx /= L.face_size(f), cy /= L.face_size(f);
    const int side = cx > cut ? 1 : 0;
    const int band = dart && cx < nx / 2.0 && cy > 1 ? 1 : 0;
    for (Index v : L.face(f)) {
      auto [it, added] = value_of.emplace(std::tuple(v, side, band), Index(m.uv.size() / 2));
      if (added) m.uv.insert(m.uv.end(), {m.mesh.positions[3 * v] + 0.3 * side, m.mesh.positions[3 * v + 1] + 0.2 * band});
      m.indices.push_back(it->second);
    }
  }
  return m;
}

// A cube with each face its own UV square: every edge a seam, every vertex three values.
UvMesh unwrapped_cube() {
  UvMesh m{cube(), {}, {}, {}};
  const Level L = m.mesh.level();
  for (Index f = 0; f < L.face_count(); ++f)
    for (int k = 0; k < L.face_size(f); ++k) {
      m.indices.push_back(Index(m.uv.size() / 2));
      m.uv.insert(m.uv.end(), {double(f) + (k == 1 || k == 2), double(k >= 2) + 0.1 * f});
    }
  return m;
}

const FaceVaryingLinear kModes[] = {FaceVaryingLinear::None,         FaceVaryingLinear::CornersOnly,
                                    FaceVaryingLinear::CornersPlus1, FaceVaryingLinear::CornersPlus2,
                                    FaceVaryingLinear::Boundaries,   FaceVaryingLinear::All};

void check_all_modes(const UvMesh& m, const std::string& scheme, OsdScheme osd_scheme, int levels) {
  for (OsdBoundary boundary : {OsdBoundary::EdgesAndCorners, OsdBoundary::EdgesOnly})
    for (FaceVaryingLinear mode : kModes) {
      const std::string mode_name = face_varying_linear_name(mode);
      const int boundary_mode = int(boundary);
      CAPTURE(mode_name);
      CAPTURE(boundary_mode);
      OsdOptions o;
      o.scheme = osd_scheme;
      o.boundary = boundary;
      CHECK(worst_difference(m, scheme, o, mode, levels) < 1e-12);
    }
}

}  // namespace

TEST_CASE("Catmull-Clark: a seam across a grid, and a dart, agree with Far in every mode") {
  check_all_modes(seamed_grid(4, 3, 2, false, false), "catmull-clark", OsdScheme::CatmullClark, 3);
  check_all_modes(seamed_grid(4, 3, 2, true, false), "catmull-clark", OsdScheme::CatmullClark, 3);
}

TEST_CASE("Catmull-Clark: a cube unwrapped face by face (three values at every vertex)") {
  check_all_modes(unwrapped_cube(), "catmull-clark", OsdScheme::CatmullClark, 3);
}

TEST_CASE("Catmull-Clark: a seam beside a sharp crease and a semi-sharp one") {
  UvMesh m = seamed_grid(4, 3, 2, false, false);
  m.creases = {{1, 6, 10.f}, {6, 11, 10.f}, {7, 8, 1.5f}};
  check_all_modes(m, "catmull-clark", OsdScheme::CatmullClark, 3);
}

TEST_CASE("Loop: a seam across a triangulated grid, and a dart") {
  check_all_modes(seamed_grid(4, 3, 2, false, true), "loop", OsdScheme::Loop, 3);
  check_all_modes(seamed_grid(4, 3, 2, true, true), "loop", OsdScheme::Loop, 3);
}
#endif
