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

namespace subdiv_test {

struct BfrSample {
  std::array<double, 3> p{}, du{}, dv{}, duu{}, duv{}, dvv{};
};

class BfrLimit {
public:
  BfrLimit(const OsdMesh& mesh, const OsdOptions& options, int approx_smooth, int approx_sharp)
      : xyz_(mesh.xyz), osd_(osd_refine(mesh, options, 0)) {
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

private:
  std::vector<double> xyz_;
  OsdRefinement osd_;
  std::unique_ptr<OpenSubdiv::Bfr::RefinerSurfaceFactory<>> factory_;
};

}  // namespace subdiv_test

#endif
