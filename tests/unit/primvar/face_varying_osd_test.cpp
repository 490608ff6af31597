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

// A mesh with a face-varying channel: 2 values per entry, one index per face corner.
struct UvMesh {
  Mesh mesh;
  std::vector<double> uv;
  std::vector<Index> indices;
  std::vector<OsdCrease> creases;
};

// Our face-varying refinement of `m` and Far's, compared at levels 1..levels.
double worst_difference(const UvMesh& m, const std::string& scheme_name, OsdOptions o, FaceVaryingLinear mode,
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
  OsdMesh om;
  om.vertex_count = m.mesh.vertex_count;
  om.face_offsets.assign(m.mesh.offsets.begin(), m.mesh.offsets.end());
  om.face_vertices.assign(m.mesh.corners.begin(), m.mesh.corners.end());
  om.xyz = m.mesh.positions;
  om.creases = m.creases;
  om.fvar_components = 2;
  om.fvar_values = m.uv;
  om.fvar_indices.assign(m.indices.begin(), m.indices.end());
  o.fvar_linear = int(mode);  // the same order as Sdc::Options::FVarLinearInterpolation
  const OsdRefinement far = osd_refine(om, o, levels);
  std::vector<std::vector<double>> values;
  std::vector<std::vector<Index>> corners;
  for (const auto& level : ours) values.push_back(level.values), corners.push_back(level.indices);
  return max_face_varying_difference(far, h, values, corners, 2, levels);
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
