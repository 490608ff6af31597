// The sampled limit surface as every front-end writes it (framework/pipeline/limit_mesh.h):
// rational weights are honoured (uniform weights change nothing, projective invariance;
// at a base vertex the sample is the rational limit position `refine --limit` gives through
// the limit masks, a separate path), and face-varying channels are sampled at every corner,
// split exactly at their seams.
#include <doctest/doctest.h>

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/pipeline/adaptive_request.h"
#include "framework/pipeline/evaluate_request.h"
#include "framework/pipeline/limit_mesh.h"
#include "framework/pipeline/rational_weights.h"
#include "framework/pipeline/refine_pipeline.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

MeshData with_weights(MeshData m, const std::vector<double>& w) {
  m.point_data.push_back(DataArray{kWeightArrayName, 1, w, false});
  return m;
}

PreparedEvaluation prepared(MeshData m, const std::string& scheme = "catmull-clark") {
  EvaluateRequest r;
  r.mesh = std::move(m);
  r.mesh_name = "test mesh";
  r.scheme.text = scheme;
  return prepare_evaluation(std::move(r));
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double d = 0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

// A 3 x 2 grid of unit quads in z = 0 whose texture coordinates have a seam along x = 2:
// (x, y) left of it, (x + 10, y) right of it (the seam's points carry both).
MeshData grid_with_seam() {
  MeshData m = test::mesh_data(test::grid(3, 2));
  FaceVaryingArray uv{"uv", 2, {}, {}, ArrayRole::TextureCoordinates};
  std::map<std::pair<Index, bool>, Index> value_of;  // (vertex, right of the seam) -> value
  for (Index f = 0; f < m.face_count(); ++f) {
    double cx = 0;
    for (Index k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k) cx += m.positions[3 * size_t(m.face_vertices[k])];
    const bool right = cx / (m.face_offsets[f + 1] - m.face_offsets[f]) > 2;
    for (Index k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k) {
      const Index vertex = m.face_vertices[k];
      const auto [it, added] = value_of.emplace(std::make_pair(vertex, right), uv.value_count());
      if (added) {
        const double* p = &m.positions[3 * size_t(vertex)];
        uv.values.insert(uv.values.end(), {p[0] + (right ? 10.0 : 0.0), p[1]});
      }
      uv.indices.push_back(it->second);
    }
  }
  m.face_varying.push_back(std::move(uv));
  return m;
}

TEST_CASE("uniform weights sample the polynomial surface; other weights move it, to the rational limit masks") {
  const MeshData cube = test::mesh_data(test::cube());
  const MeshData plain = sampled_limit_mesh(prepared(cube), 4);
  const MeshData uniform = sampled_limit_mesh(prepared(with_weights(cube, std::vector<double>(8, 2.5))), 4);
  CHECK(largest_difference(plain.positions, uniform.positions) < 1e-14);

  std::vector<double> w = {1, 3, 1, 0.5, 2, 1, 1, 4};
  const MeshData rational = sampled_limit_mesh(prepared(with_weights(cube, w)), 4);
  CHECK(largest_difference(plain.positions, rational.positions) > 1e-2);
  // The samples at base vertices against refine's limit positions of level 0 (limit masks
  // applied to (w p, w), projected).
  RefineRequest r;
  r.mesh = with_weights(cube, w);
  r.mesh_name = "test mesh";
  r.scheme.text = "catmull-clark";
  r.levels = 0;
  r.limit_positions = true;
  const RefineResult limits = refine_mesh(std::move(r));
  const std::vector<double>& expected = limits.levels.back().positions;
  const DataArray& base_face = rational.point_data[1];
  const DataArray& uv = rational.point_data[2];
  REQUIRE(base_face.name == "base_face");
  int corners_checked = 0;
  for (Index i = 0; i < rational.vertex_count(); ++i) {
    const double u = uv.values[2 * size_t(i)], v = uv.values[2 * size_t(i) + 1];
    if ((u != 0 && u != 1) || (v != 0 && v != 1)) continue;
    const Index f = Index(base_face.values[size_t(i)]);
    const int k = u == 0 ? (v == 0 ? 0 : 3) : (v == 0 ? 1 : 2);  // the quad's corner at (u, v)
    const Index vertex = cube.face_vertices[size_t(cube.face_offsets[f] + k)];
    for (int c = 0; c < 3; ++c)
      CHECK(rational.positions[3 * size_t(i) + c] ==
            doctest::Approx(expected[3 * size_t(vertex) + c]).epsilon(1e-12));
    ++corners_checked;
  }
  CHECK(corners_checked == 8);
}

TEST_CASE("a channel holding the positions, without seams, samples to the sampled points") {
  // The same scheme on the same values: the channel's limit is the surface's (face-varying
  // mode none: smooth everywhere, on a closed mesh).
  MeshData cube = test::mesh_data(test::cube());
  cube.face_varying.push_back(FaceVaryingArray{"copy", 3, cube.positions, {cube.face_vertices.begin(), cube.face_vertices.end()}});
  EvaluateRequest r;
  r.mesh = cube;
  r.mesh_name = "test mesh";
  r.scheme.text = "catmull-clark";
  r.shape.face_varying = FaceVaryingLinear::None;
  const MeshData m = sampled_limit_mesh(prepare_evaluation(std::move(r)), 4);
  REQUIRE(m.face_varying.size() == 1);
  const FaceVaryingArray& copy = m.face_varying[0];
  CHECK(copy.value_count() == m.vertex_count());  // no seam: one value per point
  for (size_t k = 0; k < copy.indices.size(); ++k)
    for (int c = 0; c < 3; ++c)
      CHECK(copy.values[3 * size_t(copy.indices[k]) + c] ==
            doctest::Approx(m.positions[3 * size_t(m.face_vertices[k]) + c]).epsilon(1e-12));
}

TEST_CASE("texture coordinates are sampled at every corner and split exactly at their seam") {
  const int N = 4;
  const MeshData m = sampled_limit_mesh(prepared(grid_with_seam()), N);
  REQUIRE(m.face_varying.size() == 1);
  const FaceVaryingArray& uv = m.face_varying[0];
  CHECK(uv.role == ArrayRole::TextureCoordinates);
  REQUIRE(uv.indices.size() == m.face_vertices.size());
  // The seam (x = 2, y from 0 to 2) has 2 N + 1 samples, each with a value on either side.
  CHECK(uv.value_count() == m.vertex_count() + 2 * N + 1);
  // The default mode (OpenSubdiv's "all") is bilinear in each face, so each corner's value
  // lies in its face's range: x in [0, 2] left of the seam, x + 10 in [12, 13] right of it;
  // the seam's samples take 2 on the left and 12 on the right.
  const DataArray& base_face = m.cell_data[0];
  std::set<Index> seam_values_left, seam_values_right;
  for (Index f = 0; f < m.face_count(); ++f) {
    const Index b = Index(base_face.values[size_t(f)]);
    const bool right = b % 3 == 2;  // test::grid numbers faces row by row, 3 per row
    for (Index k = m.face_offsets[f]; k < m.face_offsets[f + 1]; ++k) {
      const double* value = &uv.values[2 * size_t(uv.indices[k])];
      CHECK(value[0] >= (right ? 12.0 : 0.0) - 1e-12);
      CHECK(value[0] <= (right ? 13.0 : 2.0) + 1e-12);
      if (std::abs(value[0] - 2.0) < 1e-12) seam_values_left.insert(uv.indices[k]);
      if (std::abs(value[0] - 12.0) < 1e-12) seam_values_right.insert(uv.indices[k]);
    }
  }
  CHECK(seam_values_left.size() == size_t(2 * N + 1));
  CHECK(seam_values_right.size() == size_t(2 * N + 1));
}

// Points of `m` whose Normals are exactly (0, 0, 0); every other one must be a unit vector.
size_t zero_normals(const MeshData& m) {
  const DataArray& n = m.point_data[0];
  REQUIRE(n.name == "Normals");
  size_t zero = 0;
  for (size_t i = 0; i < n.values.size(); i += 3) {
    const double length = std::hypot(n.values[i], n.values[i + 1], n.values[i + 2]);
    if (length == 0) ++zero;
    else CHECK(length == doctest::Approx(1.0).epsilon(1e-12));
  }
  return zero;
}

TEST_CASE("where the surface has no normal, Normals are (0, 0, 0) and the mesh's warnings say how many and where") {
  // A surface without a normal there: du x dv = 0. All control points equal make every
  // derivative 0, so every sample is such a point; the cube has a normal everywhere.
  const MeshData fine = sampled_limit_mesh(prepared(test::mesh_data(test::cube())), 2);
  CHECK(zero_normals(fine) == 0);
  CHECK(fine.warnings.empty());
  MeshData collapsed = test::mesh_data(test::cube());
  for (size_t i = 0; i < collapsed.positions.size(); ++i) collapsed.positions[i] = double(i % 3 + 1);
  const MeshData m = sampled_limit_mesh(prepared(collapsed), 2);
  CHECK(zero_normals(m) == size_t(m.vertex_count()));
  REQUIRE(m.warnings.size() == 1);
  CHECK(m.warnings[0] == fmt::format("the limit surface has no normal at {} of {} points (the first at face 0, (u, v) "
                                     "= (0, 0)): its tangents are parallel or zero there (coincident control points, "
                                     "a surface folded flat) or the scheme gives no derivatives; their Normals are "
                                     "(0, 0, 0)",
                                     m.vertex_count(), m.vertex_count()));
  // A pillow: two quads on the same four points, back to back. Its limit is flat and folds
  // back along the four edges, where du x dv vanishes; inside the faces it has a normal.
  test::Mesh pillow;
  for (int i = 0; i < 4; ++i) pillow.add_vertex(i == 1 || i == 2, i >= 2, 0);
  pillow.add_face({0, 1, 2, 3});
  pillow.add_face({3, 2, 1, 0});
  const MeshData folded = sampled_limit_mesh(prepared(test::mesh_data(pillow)), 4);
  const size_t zero = zero_normals(folded);
  CHECK(zero > 0);
  CHECK(zero < size_t(folded.vertex_count()));
  REQUIRE(folded.warnings.size() == 1);
  CHECK(folded.warnings[0].find(fmt::format("no normal at {} of {} points", zero, folded.vertex_count())) != std::string::npos);
}

TEST_CASE("adaptive meshes carry float point arrays but not normals, as refinement does") {
  MeshData cube = test::mesh_data(test::cube());
  cube.point_data.push_back(DataArray{"n", 3, cube.positions, false, ArrayRole::Normals});
  cube.point_data.push_back(DataArray{"height", 1, std::vector<double>(8, 1.0), false});
  RefineRequest r;
  r.mesh = std::move(cube);
  r.mesh_name = "test mesh";
  r.scheme.text = "catmull-clark";
  r.levels = 2;
  AdaptiveRequest a;
  a.refine = std::move(r);
  const AdaptiveResult result = refine_adaptive_request(std::move(a));
  REQUIRE(result.point_arrays.size() == 1);
  CHECK(result.point_arrays[0].name == "height");
  bool said = false;
  for (const std::string& note : result.notes) said = said || note.find("'n' holds normals") != std::string::npos;
  CHECK(said);
}

}  // namespace
}  // namespace subdiv
