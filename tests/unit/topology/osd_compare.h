#pragma once
// Refines a FeatureMesh with SubdivKit and with OpenSubdiv's Far and compares positions at
// every level, for the non-manifold, hole and option tests of this folder.
#include <algorithm>
#include <doctest/doctest.h>
#include <fmt/format.h>

#include "support/osd_reference.h"
#include "unit/features/feature_meshes.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

#include "framework/engine/refiner.h"
#include "framework/io/mesh_level.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"

namespace subdiv::nonmanifold_test {

constexpr double kTolerance = 1e-12;

struct Setup {
  BoundaryInterpolation boundary = BoundaryInterpolation::EdgesAndCorners;
  CreaseMethod method = CreaseMethod::Uniform;
  std::string name() const {
    const char* b = boundary == BoundaryInterpolation::None        ? "none"
                    : boundary == BoundaryInterpolation::EdgesOnly ? "edges"
                                                                   : "edges-and-corners";
    return fmt::format("--boundary {} --crease-method {}", b, method == CreaseMethod::Chaikin ? "chaikin" : "uniform");
  }
};

inline const Setup kSetups[] = {
    {BoundaryInterpolation::EdgesAndCorners, CreaseMethod::Uniform}, {BoundaryInterpolation::EdgesOnly, CreaseMethod::Uniform},
    {BoundaryInterpolation::None, CreaseMethod::Uniform},            {BoundaryInterpolation::EdgesAndCorners, CreaseMethod::Chaikin},
    {BoundaryInterpolation::EdgesOnly, CreaseMethod::Chaikin},       {BoundaryInterpolation::None, CreaseMethod::Chaikin},
};

inline subdiv_test::OsdMesh to_osd(const MeshData& m) {
  subdiv_test::OsdMesh o;
  o.vertex_count = m.vertex_count();
  o.face_offsets.assign(m.face_offsets.begin(), m.face_offsets.end());
  o.face_vertices.assign(m.face_vertices.begin(), m.face_vertices.end());
  o.xyz = m.positions;
  for (const auto& c : m.creases) o.creases.push_back({c.v0, c.v1, float(c.sharpness)});
  for (const auto& c : m.corners) o.corners.push_back({c.v, float(c.sharpness)});
  o.holes.assign(m.holes.begin(), m.holes.end());
  return o;
}

inline subdiv_test::OsdOptions osd_options(const std::string& scheme, const Setup& s, bool smooth_triangles = false) {
  subdiv_test::OsdOptions o;
  o.scheme = scheme == "loop"       ? subdiv_test::OsdScheme::Loop
             : scheme == "bilinear" ? subdiv_test::OsdScheme::Bilinear
                                    : subdiv_test::OsdScheme::CatmullClark;
  o.boundary = s.boundary == BoundaryInterpolation::None        ? subdiv_test::OsdBoundary::None
               : s.boundary == BoundaryInterpolation::EdgesOnly ? subdiv_test::OsdBoundary::EdgesOnly
                                                                : subdiv_test::OsdBoundary::EdgesAndCorners;
  o.creasing = s.method == CreaseMethod::Chaikin ? subdiv_test::OsdCreasing::Chaikin : subdiv_test::OsdCreasing::Uniform;
  o.smooth_triangles = smooth_triangles;
  return o;
}

// Positions at levels 1..levels equal OpenSubdiv's to kTolerance (through stencil tables
// and straight from the rules), and every face is a hole exactly where OpenSubdiv's is.
// Returns the largest difference of the tables' positions from OpenSubdiv's.
inline double check_agreement(const feature_test::FeatureMesh& fm, const std::string& scheme_name, const Setup& setup,
                            int levels = 3, const ParameterOverrides& params = {}, bool smooth_triangles = false) {
  const auto scheme = load_scheme(scheme_name, params);
  RefineOptions options;
  options.levels = levels;
  options.features = {setup.boundary, setup.method};
  const Hierarchy h = refine(*scheme, level_from_mesh(fm.mesh, fm.name), options);
  const auto osd = subdiv_test::osd_refine(to_osd(fm.mesh), osd_options(scheme_name, setup, smooth_triangles), levels);
  std::vector<double> direct = fm.mesh.positions;
  double largest = 0;
  for (int l = 1; l <= levels; ++l) {
    const auto ours = interpolate(h, l, fm.mesh.positions, 3);
    const auto expected = subdiv_test::osd_in_our_order(osd, h, l);
    direct = step_values(*scheme, h, l - 1, direct, 3, options);
    const subdiv_test::WorstVertex w = subdiv_test::worst_vertex(ours, expected);
    const double worst = w.difference;  // named copies: clang 14 cannot capture bindings in INFO
    largest = std::max(largest, worst);
    const size_t at = w.vertex;
    const auto& origin = h.origins[size_t(l) - 1];
    INFO(fmt::format("{} with {}, {}, level {}: worst vertex {} (origin kind {} parent {}) differs by {:.3e}", fm.name,
                     scheme_name, setup.name(), l, at, int(origin.kind[at]), origin.parent[at], worst));
    CHECK(worst < kTolerance);
    CHECK(subdiv_test::max_abs_difference(direct, expected) < kTolerance);
    if (worst >= kTolerance) return largest;  // later levels inherit the difference
  }
  // Holes: ours per face against OpenSubdiv's, faces matched by their corners.
  for (int l = 0; l <= levels; ++l) {
    const Level& L = h.levels[size_t(l)];
    const auto vmap = subdiv_test::our_to_osd_vertices(osd, h, l);
    const auto fmap = subdiv_test::detail::match_faces(L, osd.refiner->GetLevel(l), vmap, l);
    int differ = 0;
    for (Index f = 0; f < L.face_count(); ++f) differ += L.is_hole(f) != bool(osd.levels[size_t(l)].face_hole[size_t(fmap[f])]);
    INFO(fmt::format("{} with {}, {}, level {}: {} faces are holes on one side only", fm.name, scheme_name, setup.name(), l, differ));
    CHECK(differ == 0);
  }
  return largest;
}

inline void check_all_setups(const feature_test::FeatureMesh& fm, const std::string& scheme) {
  for (const Setup& s : kSetups) check_agreement(fm, scheme, s);
}

}  // namespace subdiv::nonmanifold_test

#endif
