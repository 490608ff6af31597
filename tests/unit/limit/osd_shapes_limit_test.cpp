// OpenSubdiv's regression shapes (tests/data/osd-shapes) evaluated at (face, u, v) against
// OpenSubdiv's Bfr with its approximation levels at 10, each shape set up as far_regression
// sets it up (unit/osd/osd_shapes.h): the mesh file read by SubdivKit's reader, as a user's
// would be. Bfr is exact away from extraordinary vertices and irregular features, and the
// random points rarely fall within its level-10 patches around them.
#include <doctest/doctest.h>

#include "support/sanitizers.h"
#include "unit/limit/bfr_surface.h"
#include "unit/osd/osd_shapes.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

#include <algorithm>
#include <cmath>
#include <random>

#include "framework/analysis/surface/limit_evaluation.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/limit/limit_surface.h"
#include "framework/util/error.h"
#include "framework/scheme/scheme_registry.h"

using namespace subdiv;
using namespace subdiv::nonmanifold_test;

namespace {

double distance(const std::vector<double>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// Points per face: an edge's middle, a corner, and random ones in the face's domain (Bfr's
// parameterisation: an n-gon's sub-faces as tiles, found with `check`).
std::vector<std::array<double, 2>> sample_points(const LimitSurface& surface, Index f, bool triangles, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::array<double, 2>> at{{0.5, 0.0}, {0.0, 0.0}};
  const int n = surface.base().face_size(f);
  const double span = triangles || n == 4 ? 1.0 : std::ceil(std::sqrt(double(n)));
  while (at.size() < 5) {
    double u = span * unit(rng), v = span * unit(rng);
    if (triangles && u + v > 1) u = 1 - u, v = 1 - v;
    if (surface.check(f, u, v).empty()) at.push_back({u, v});
  }
  return at;
}

struct ShapeResult {
  double position = 0, derivative = 0;
  int points = 0, vertices = 0;  // points evaluated; of them, vertices compared with their masks
  std::string refused;  // the first refusal's message
};

ShapeResult compare_shape(const std::filesystem::path& file) {
  const std::string shape = file.stem().string();
  const MeshData mesh = read_mesh(file);
  const std::string scheme_name = scheme_of(shape);
  const bool smooth = scheme_name == "catmull-clark" && mesh.options.smooth_triangles == "smooth";
  const ParameterOverrides params = smooth ? ParameterOverrides{{"triangles", "smooth"}} : ParameterOverrides{};
  const Setup setup = setup_of(mesh.options);
  LimitSurfaceOptions lo;
  lo.features = {setup.boundary, setup.method};
  const LimitSurface surface(load_scheme(scheme_name, params), level_from_mesh(mesh, shape), lo);
  const subdiv_test::BfrLimit bfr(to_osd(mesh), osd_options(scheme_name, setup, smooth), 10, 10);
  LimitOptions mask_options;
  mask_options.features = lo.features;
  LimitResult masks;  // empty where the masks do not take the mesh (non-manifold ones): corners unchecked
  try {
    masks = limit_positions(*load_scheme(scheme_name, params), surface.base(), mesh.positions, mask_options);
  } catch (const Error&) {
  }
  const bool triangles = scheme_name == "loop";
  std::mt19937 rng(3);
  ShapeResult r;
  // At most about 100 faces of a shape (its faces evenly spread; a third of that under the
  // sanitizers): the big ones (car, bishop, rook, pawn) would take most of the time and show
  // nothing the others do not.
  const Index step = std::max<Index>(1, surface.base().face_count() * subdiv_test::kSanitizerThinning / 100);
  for (Index f = 0; f < surface.base().face_count(); f += step) {
    if (surface.base().is_hole(f)) continue;
    for (const auto& uv : sample_points(surface, f, triangles, rng)) {
      try {
        const LimitSample ours = surface.evaluate(f, uv[0], uv[1], mesh.positions, 3);
        const bool corner = uv[0] == 0 && uv[1] == 0;
        if (corner) {
          // At a vertex Bfr approximates where the vertex is irregular (its sharp patches
          // at level 10 were up to 1.7e-3 off on catmark_chaikin1, 2.2e-5 on
          // catmark_inf_crease1, where refinement to level 10 extrapolates to ours); the
          // reference there is the vertex's limit mask (refinement until its features have
          // decayed, then the eigen-analysis), where that is exact.
          const Index v = surface.base().face(f)[0];
          if (!masks.exact.empty() && masks.exact[size_t(v)]) {
            const std::array<double, 3> mask{masks.positions[size_t(3 * v)], masks.positions[size_t(3 * v + 1)],
                                             masks.positions[size_t(3 * v + 2)]};
            r.position = std::max(r.position, distance(ours.position, mask));
            ++r.vertices;
          }
        } else {
          const auto ref = bfr.evaluate(int(f), uv[0], uv[1]);
          r.position = std::max(r.position, distance(ours.position, ref.p));
          if (ours.has_derivatives)
            r.derivative = std::max({r.derivative, distance(ours.du, ref.du), distance(ours.dv, ref.dv)});
        }
        ++r.points;
      } catch (const Error& e) {
        if (r.refused.empty()) r.refused = e.what();
      }
    }
  }
  return r;
}

}  // namespace

TEST_CASE("OpenSubdiv's regression shapes: the limit at (face, u, v) is Bfr's") {
  // Catmull-Clark and Loop shapes (bilinear ones are their own faces), with their tags,
  // boundary modes, crease methods, holes and non-manifold elements.
  int shapes = 0, vertices = 0;
  double position = 0, derivative = 0;
  for (const auto& file : shape_files()) {
    const std::string shape = file.stem().string();
    if (scheme_of(shape) == "bilinear") continue;
    CAPTURE(shape);
    ShapeResult r;
    try {
      r = compare_shape(file);
    } catch (const std::exception& e) {
      FAIL_CHECK(shape << ": " << std::string(e.what()));
      continue;
    }
    ++shapes;
    CHECK(r.points > 0);
    CHECK(r.position < 1e-12);
    CHECK(r.derivative < 1e-10);
    position = std::max(position, r.position), derivative = std::max(derivative, r.derivative);
    vertices += r.vertices;
    if (shape == "loop_val2_interior") {
      // Two triangles back to back: refused with the reason, not an internal error.
      CHECK(r.refused.find("thinner than the scheme's stencils") != std::string::npos);
    } else {
      // Catmull-Clark's interior vertices of valence 2 (the catmark_val2_* shapes,
      // catmark_gregory_test8) included: their corners are their limit masks.
      CHECK(r.refused.empty());
    }
  }
  CHECK(shapes >= 110);
  CHECK(vertices > 1000);
  MESSAGE(fmt::format("{} shapes: positions within {:.2g} of Bfr's and the vertices' masks ({} vertices), derivatives "
                      "within {:.2g}", shapes, position, vertices, derivative));
}

TEST_CASE("A point the evaluation refuses is named in the error: face and (u, v)") {
  // loop_val2_interior is non-manifold (its first two triangles, back to back, touch two
  // more at a vertex): its points go through the surface's manifold sheets, whose faces are
  // numbered their own way, yet the message names the face and (u, v) the caller gave, once.
  const std::string shape = "loop_val2_interior";
  const MeshData mesh = read_mesh(std::filesystem::path(kShapes) / (shape + ".obj"));
  const LimitSurface surface(load_scheme("loop"), level_from_mesh(mesh, shape));
  const std::string named = "face 1 at (u, v) = (0.25, 0.5): the neighbourhood of this point wraps around";
  CHECK_THROWS_WITH_AS(surface.evaluate(1, 0.25, 0.5, mesh.positions, 3), doctest::Contains(named.c_str()), Error);
  CHECK_THROWS_WITH_AS(surface.stencil(1, 0.25, 0.5), doctest::Contains(named.c_str()), Error);
  try {
    (void)surface.stencil(1, 0.25, 0.5);
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("(u, v)", std::string(e.what()).find("(u, v)") + 1) == std::string::npos);
  }
  // The two triangles apart from the pillow evaluate; a face that does not exist is named by
  // its own check, not twice.
  CHECK_NOTHROW((void)surface.evaluate(2, 0.25, 0.5, mesh.positions, 3));
  CHECK_THROWS_WITH_AS(surface.evaluate(10, 0.25, 0.5, mesh.positions, 3),
                       doctest::Contains("face 10 does not exist: the mesh has 10 faces"), Error);
}

TEST_CASE("OpenSubdiv's valence-360 poles: the limit at the pole is its limit mask, near it Bfr's") {
  // catmark_pole360 (triangles round the pole, Catmull-Clark) and loop_pole360: the pole is
  // corner 2 of face 1. Its limit is the mask from the eigen-analysis (valence 360: the
  // sector rotation's Fourier blocks); a point 0.02 from it lies outside Bfr's level-10
  // irregular patches, where Bfr is exact.
  struct Pole {
    const char* shape;
    std::array<double, 2> at, near;  // the pole's (u, v) in face 1, and a point near it
  };
  for (const Pole& pole : {Pole{"catmark_pole360", {0.0, 1.0}, {0.02, 1.02}}, Pole{"loop_pole360", {0.0, 1.0}, {0.02, 0.96}}}) {
    CAPTURE(pole.shape);
    const std::string shape = pole.shape;
    const MeshData mesh = read_mesh(std::filesystem::path(kShapes) / (shape + ".obj"));
    const std::string scheme_name = scheme_of(shape);
    const Setup setup = setup_of(mesh.options);
    LimitSurfaceOptions lo;
    lo.features = {setup.boundary, setup.method};
    const auto scheme = load_scheme(scheme_name);
    const LimitSurface surface(scheme, level_from_mesh(mesh, shape), lo);
    const Index v = surface.base().face(1)[2];
    REQUIRE(surface.base().valence(v) == 360);
    LimitOptions mask_options;
    mask_options.features = lo.features;
    const LimitResult masks = limit_positions(*scheme, surface.base(), mesh.positions, mask_options);
    REQUIRE(masks.exact[size_t(v)] == 1);
    CHECK(masks.normal_exact[size_t(v)] == 1);
    const LimitSample at = surface.evaluate(1, pole.at[0], pole.at[1], mesh.positions, 3);
    CHECK(distance(at.position, {masks.positions[size_t(3 * v)], masks.positions[size_t(3 * v + 1)],
                                 masks.positions[size_t(3 * v + 2)]}) < 1e-12);
    const subdiv_test::BfrLimit bfr(to_osd(mesh), osd_options(scheme_name, setup, false), 10, 10);
    const LimitSample near = surface.evaluate(1, pole.near[0], pole.near[1], mesh.positions, 3);
    const auto ref = bfr.evaluate(1, pole.near[0], pole.near[1]);
    CHECK(distance(near.position, ref.p) < 1e-12);
    REQUIRE(near.has_derivatives);
    CHECK(distance(near.du, ref.du) < 1e-10);
    CHECK(distance(near.dv, ref.dv) < 1e-10);
  }
}

#endif
