// Face-varying arrays on adaptive meshes (framework/pipeline/adaptive_request.h): with limit
// positions each face corner gets the channel's limit at its (base face, u, v). Checked by
// closed forms independent of the evaluator: in the mode `all` (OpenSubdiv's default) the
// channel is bilinear over each base face; in the mode `none` a seamless channel that is an
// affine image of the positions refines like them, so its limit is that image of the limit
// positions. Without limit positions the channels are refined with the faces: the mode `all`
// gives the same bilinear values (a level's are the limit's), the mode `none` that image of
// the level's positions (adaptive_face_varying_levels_test.cpp compares every mode with
// uniform face-varying refinement).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/pipeline/adaptive_request.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// The cube with a seamless two-component channel (one value per vertex, indexed by vertex):
// (x + 2z, y - z + 0.5), an affine image of the positions.
MeshData cube_with_channel() {
  MeshData d = test::mesh_data(test::cube());
  FaceVaryingArray a{"st", 2, {}, {d.face_vertices.begin(), d.face_vertices.end()}, ArrayRole::Data};
  for (size_t v = 0; v < d.positions.size() / 3; ++v) {
    const double x = d.positions[3 * v], y = d.positions[3 * v + 1], z = d.positions[3 * v + 2];
    a.values.insert(a.values.end(), {x + 2 * z, y - z + 0.5});
  }
  d.face_varying.push_back(std::move(a));
  return d;
}

AdaptiveResult adaptive(FaceVaryingLinear mode, bool limit,
                        AdaptiveTransitions transitions = AdaptiveTransitions::Polygons) {
  AdaptiveRequest r;
  r.refine.mesh = cube_with_channel();
  r.refine.mesh_name = "cube";
  r.refine.scheme.text = "catmull-clark";
  r.refine.shape.face_varying = mode;
  r.refine.levels = 3;
  r.limit = limit;
  r.transitions = transitions;
  return refine_adaptive_request(std::move(r));
}

}  // namespace

TEST_CASE("adaptive meshes carry face-varying channels: bilinear in the mode all, on the limit and at the levels") {
  // OpenSubdiv's linear-all face-varying interpolation refines each face's values
  // bilinearly, so a level's corner has the same value as the limit there. With the
  // transitions as triangles and quads each corner keeps its value.
  for (const auto& run : {std::pair{true, AdaptiveTransitions::Polygons}, std::pair{false, AdaptiveTransitions::Polygons},
                          std::pair{true, AdaptiveTransitions::Triangles},
                          std::pair{false, AdaptiveTransitions::Triangles}}) {
    const bool limit = run.first;  // not a structured binding: clang 14 cannot capture those
    const AdaptiveTransitions transitions = run.second;
    CAPTURE(limit);
    CAPTURE(int(transitions));
    const MeshData base = cube_with_channel();
    const AdaptiveResult a = adaptive(FaceVaryingLinear::All, limit, transitions);
    REQUIRE(a.face_varying.size() == 1);
    const FaceVaryingArray& st = a.face_varying.front();
    REQUIRE(st.indices.size() == a.mesh.corner_uv.size());
    double worst = 0;
    for (size_t f = 0; f + 1 < a.mesh.face_offsets.size(); ++f) {
      const Index b = a.mesh.base_face[f];
      for (Index c = a.mesh.face_offsets[f]; c < a.mesh.face_offsets[f + 1]; ++c) {
        const double u = a.mesh.corner_uv[size_t(c)][0], v = a.mesh.corner_uv[size_t(c)][1];
        const double w[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
        for (int k = 0; k < 2; ++k) {
          double expected = 0;
          for (int i = 0; i < 4; ++i)
            expected += w[i] * base.face_varying[0].values[2 * size_t(base.face_varying[0].indices[size_t(4 * b + i)]) + size_t(k)];
          worst = std::max(worst, std::abs(st.values[2 * size_t(st.indices[size_t(c)]) + size_t(k)] - expected));
        }
      }
    }
    CHECK(worst < 1e-14);
  }
}

TEST_CASE("adaptive meshes carry face-varying channels on the limit: in the mode none, the positions' image") {
  const AdaptiveResult a = adaptive(FaceVaryingLinear::None, true);
  REQUIRE(a.face_varying.size() == 1);
  const FaceVaryingArray& st = a.face_varying.front();
  double worst = 0;
  for (size_t c = 0; c < st.indices.size(); ++c) {
    const Index v = a.mesh.face_vertices[c];
    const double x = a.mesh.positions[3 * size_t(v)], y = a.mesh.positions[3 * size_t(v) + 1],
                 z = a.mesh.positions[3 * size_t(v) + 2];
    worst = std::max({worst, std::abs(st.values[2 * size_t(st.indices[c])] - (x + 2 * z)),
                      std::abs(st.values[2 * size_t(st.indices[c]) + 1] - (y - z + 0.5))});
  }
  CHECK(worst < 1e-13);
  // The written mesh has them.
  AdaptiveResult moved = adaptive(FaceVaryingLinear::None, true);
  const MeshData m = adaptive_mesh_data(std::move(moved.mesh), std::move(moved.point_arrays),
                                        std::move(moved.face_varying));
  REQUIRE(m.face_varying.size() == 1);
  CHECK(m.face_varying[0].name == "st");
  CHECK(m.face_varying[0].indices.size() == m.face_vertices.size());
}

TEST_CASE("without limit positions, smooth face-varying channels are refined like the positions") {
  const AdaptiveResult a = adaptive(FaceVaryingLinear::None, false);
  REQUIRE(a.face_varying.size() == 1);
  const FaceVaryingArray& st = a.face_varying.front();
  REQUIRE(st.indices.size() == a.mesh.face_vertices.size());
  double worst = 0;
  for (size_t c = 0; c < st.indices.size(); ++c) {
    const size_t v = size_t(a.mesh.face_vertices[c]), i = 2 * size_t(st.indices[c]);
    const double x = a.mesh.positions[3 * v], y = a.mesh.positions[3 * v + 1], z = a.mesh.positions[3 * v + 2];
    worst = std::max({worst, std::abs(st.values[i] - (x + 2 * z)), std::abs(st.values[i + 1] - (y - z + 0.5))});
  }
  CHECK(worst < 1e-14);
  for (const std::string& n : a.notes) CHECK(n.find("face-varying") == std::string::npos);
}

}  // namespace subdiv
