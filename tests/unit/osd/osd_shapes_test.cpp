// OpenSubdiv's own regression shapes (tests/data/osd-shapes, taken from OpenSubdiv 3.5.0's
// regression/shapes; README.md there says which were left out) refined by SubdivKit and by
// OpenSubdiv's Far: positions equal to 1e-12 at levels 1-3, holes where Far has them.
//
// Each shape is refined as OpenSubdiv's far_regression refines it (regression/common/
// far_utils.h, GetSdcOptions): the scheme from its name (bilinear_, catmark_, loop_), the
// boundary interpolation from its `t interpolateboundary` tag or VTX_BOUNDARY_EDGE_ONLY
// without one, the crease method and the triangle rule from its tags, its creases, corners
// and holes as tagged. The file is read by SubdivKit's OBJ reader, as a user's would be.
#include <doctest/doctest.h>

#include "support/osd_reference.h"
#include "unit/osd/osd_shapes.h"
#include "unit/topology/osd_compare.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

#include <algorithm>
#include <filesystem>

#include "framework/io/mesh_read.h"

using namespace subdiv;
using namespace subdiv::nonmanifold_test;


TEST_CASE("OpenSubdiv's regression shapes agree with Far at levels 1-3") {
  const auto files = shape_files();
  REQUIRE(files.size() >= 100);
  double largest = 0;
  std::string at;
  for (const auto& file : files) {
    const std::string shape = file.stem().string();
    CAPTURE(shape);
    // The file as written: unused vertices (catmark_nonman_bareverts) and faces with fewer
    // than 3 distinct vertices (catmark_nonman_edges, loop_nonman_edges) included.
    const MeshData mesh = read_mesh(file);
    const std::string scheme = scheme_of(shape);
    const bool smooth = scheme == "catmull-clark" && mesh.options.smooth_triangles == "smooth";
    const ParameterOverrides params = smooth ? ParameterOverrides{{"triangles", "smooth"}} : ParameterOverrides{};
    try {
      const double d = check_agreement({shape, mesh}, scheme, setup_of(mesh.options), 3, params, smooth);
      if (d >= largest) largest = d, at = shape;
    } catch (const std::exception& e) {
      FAIL_CHECK(shape << ": " << std::string(e.what()));  // one shape's failure must not hide the others'
    }
  }
  MESSAGE(fmt::format("{} shapes; largest difference from Far {:.3g} ({})", files.size(), largest, at));
}

#endif
