#pragma once
// OpenSubdiv's Bfr as the reference for limit evaluation: a face's limit surface at (u, v),
// with its approximation levels set (ApproxLevelSmooth near extraordinary vertices,
// ApproxLevelSharp near irregular creases; Bfr is exact elsewhere).
#ifdef SUBDIV_HAVE_OPENSUBDIV

#include <array>
#include <memory>
#include <vector>

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>

#include "support/osd_reference.h"
#include "support/test_meshes.h"

namespace subdiv_test {

// A test mesh as OpenSubdiv's reference builders take it, with optional crease tags.
inline OsdMesh osd_mesh(const subdiv::test::Mesh& m, std::vector<OsdCrease> creases = {}) {
  OsdMesh om;
  om.vertex_count = m.vertex_count;
  om.face_offsets.assign(m.offsets.begin(), m.offsets.end());
  om.face_vertices.assign(m.corners.begin(), m.corners.end());
  om.xyz = m.positions;
  om.creases = std::move(creases);
  return om;
}

struct BfrSample {
  std::array<double, 3> p{}, du{}, dv{}, duu{}, duv{}, dvv{};
};

class BfrLimit {
public:
  BfrLimit(const OsdMesh& mesh, const OsdOptions& options, int approx_smooth, int approx_sharp)
      : xyz_(mesh.xyz), fvar_(mesh.fvar_values), fvar_components_(mesh.fvar_components),
        osd_(osd_refine(mesh, options, 0)) {
    OpenSubdiv::Bfr::SurfaceFactory::Options o;
    o.SetApproxLevelSmooth(approx_smooth);
    o.SetApproxLevelSharp(approx_sharp);
    factory_ = std::make_unique<OpenSubdiv::Bfr::RefinerSurfaceFactory<>>(*osd_.refiner, o);
  }

  BfrSample evaluate(int face, double u, double v) const {
    OpenSubdiv::Bfr::Surface<double> s;
    if (!factory_->InitVertexSurface(face, &s)) throw std::runtime_error("Bfr: no surface for the face");
    std::vector<double> patch(3 * size_t(s.GetNumPatchPoints()));
    OpenSubdiv::Bfr::Surface<double>::PointDescriptor d(3);
    s.PreparePatchPoints(xyz_.data(), d, patch.data(), d);
    const double uv[2] = {u, v};
    BfrSample r;
    s.Evaluate(uv, patch.data(), d, r.p.data(), r.du.data(), r.dv.data(), r.duu.data(), r.duv.data(), r.dvv.data());
    return r;
  }

  // The face-varying channel's limit (Bfr's face-varying surface of channel 0); components
  // beyond the channel's are zero.
  BfrSample evaluate_fvar(int face, double u, double v) const {
    OpenSubdiv::Bfr::Surface<double> s;
    if (!factory_->InitFaceVaryingSurface(face, &s, 0)) throw std::runtime_error("Bfr: no face-varying surface");
    const int c = fvar_components_;
    std::vector<double> patch(size_t(c) * size_t(s.GetNumPatchPoints()));
    OpenSubdiv::Bfr::Surface<double>::PointDescriptor d(c);
    s.PreparePatchPoints(fvar_.data(), d, patch.data(), d);
    const double uv[2] = {u, v};
    double p[3] = {0, 0, 0}, du[3] = {0, 0, 0}, dv[3] = {0, 0, 0}, duu[3] = {0, 0, 0}, duv[3] = {0, 0, 0},
           dvv[3] = {0, 0, 0};
    s.Evaluate(uv, patch.data(), d, p, du, dv, duu, duv, dvv);
    BfrSample r;
    for (int k = 0; k < 3; ++k)
      r.p[size_t(k)] = p[k], r.du[size_t(k)] = du[k], r.dv[size_t(k)] = dv[k], r.duu[size_t(k)] = duu[k],
      r.duv[size_t(k)] = duv[k], r.dvv[size_t(k)] = dvv[k];
    return r;
  }

private:
  std::vector<double> xyz_, fvar_;
  int fvar_components_ = 0;
  OsdRefinement osd_;
  std::unique_ptr<OpenSubdiv::Bfr::RefinerSurfaceFactory<>> factory_;
};

}  // namespace subdiv_test

#endif
