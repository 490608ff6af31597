// Face-varying data (UVs) on the limit surface at (face, u, v), through the pipeline's
// evaluation request, against OpenSubdiv's Bfr face-varying surfaces in every linear
// interpolation mode.
#include <doctest/doctest.h>

#include "unit/limit/bfr_surface.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "framework/io/mesh_read.h"
#include "framework/pipeline/evaluate_request.h"
#include "support/cli_runner.h"

using namespace subdiv;

namespace {

// The mesh with its first face-varying channel bumped (so that linear and smooth modes
// differ everywhere), as an OpenSubdiv mesh.
MeshData bumped_uvs(MeshData m) {
  auto& values = m.face_varying.at(0).values;
  for (size_t i = 0; i < values.size(); ++i) values[i] += 0.05 * std::sin(3.1 * double(i) + 0.4);
  return m;
}

subdiv_test::OsdMesh osd_mesh(const MeshData& m) {
  subdiv_test::OsdMesh om;
  om.vertex_count = m.vertex_count();
  om.face_offsets.assign(m.face_offsets.begin(), m.face_offsets.end());
  om.face_vertices.assign(m.face_vertices.begin(), m.face_vertices.end());
  om.xyz = m.positions;
  const FaceVaryingArray& uv = m.face_varying.at(0);
  om.fvar_components = uv.components;
  om.fvar_values = uv.values;
  om.fvar_indices.assign(uv.indices.begin(), uv.indices.end());
  return om;
}

struct Worst {
  double value = 0, derivative = 0;
};

Worst compare(const MeshData& mesh, const char* scheme, FaceVaryingLinear mode, bool triangles, int samples) {
  EvaluateRequest r;
  r.mesh = mesh;
  r.mesh_name = "test mesh";
  r.scheme.text = scheme;
  r.shape.face_varying = mode;
  const PreparedEvaluation p = prepare_evaluation(r);
  REQUIRE(p.face_varying.size() == 1);
  subdiv_test::OsdOptions oo;
  oo.scheme = triangles ? subdiv_test::OsdScheme::Loop : subdiv_test::OsdScheme::CatmullClark;
  oo.fvar_linear = int(mode);
  const subdiv_test::BfrLimit bfr(osd_mesh(mesh), oo, 10, 10);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Index> faces;
  std::vector<double> uv;
  for (int i = 0; i < samples; ++i) {
    double u = unit(rng), v = unit(rng);
    if (triangles && u + v > 1) u = 1 - u, v = 1 - v;
    const Index f = Index(rng() % unsigned(mesh.face_count()));
    const int n = int(mesh.face_offsets[size_t(f) + 1] - mesh.face_offsets[size_t(f)]);
    if (!triangles && n != 4) {
      // A sub-face tile of Bfr's QUAD_SUBFACES layout: ceil(sqrt(n)) columns of 1/2 x 1/2 tiles.
      const int columns = int(std::ceil(std::sqrt(double(n)))), sub = int(rng() % unsigned(n));
      u = sub % columns + 0.5 * u, v = sub / columns + 0.5 * v;
    }
    faces.push_back(f);
    uv.insert(uv.end(), {u, v});
  }
  const EvaluatedPoints ours = evaluate_face_varying(p, 0, faces, uv, 1);
  const int c = ours.channels;
  Worst w;
  for (int i = 0; i < samples; ++i) {
    const auto ref = bfr.evaluate_fvar(int(faces[size_t(i)]), uv[2 * size_t(i)], uv[2 * size_t(i) + 1]);
    for (int k = 0; k < c; ++k) {
      const size_t at = size_t(i) * size_t(c) + size_t(k);
      w.value = std::max(w.value, std::fabs(ours.position[at] - ref.p[size_t(k)]));
      if (!std::isnan(ours.du[at]))
        w.derivative = std::max({w.derivative, std::fabs(ours.du[at] - ref.du[size_t(k)]),
                                 std::fabs(ours.dv[at] - ref.dv[size_t(k)])});
    }
  }
  return w;
}

}  // namespace

// UVs in islands: faces with the same group share a value at a vertex, others have their
// own (a seam between groups); values from the positions, so that no symmetry hides an error.
MeshData with_islands(MeshData m, const std::vector<int>& group) {
  FaceVaryingArray uv;
  uv.name = "uv";
  uv.components = 2;
  std::map<std::pair<Index, int>, Index> value_of;
  for (Index f = 0; f < m.face_count(); ++f)
    for (Index c = m.face_offsets[size_t(f)]; c < m.face_offsets[size_t(f) + 1]; ++c) {
      const Index v = m.face_vertices[size_t(c)];
      const auto key = std::make_pair(v, group[size_t(f)]);
      auto it = value_of.find(key);
      if (it == value_of.end()) {
        it = value_of.emplace(key, uv.value_count()).first;
        const double* x = &m.positions[3 * size_t(v)];
        uv.values.insert(uv.values.end(), {x[0] + 0.1 * x[2] + 0.7 * group[size_t(f)] + 0.05 * std::sin(1.3 * v),
                                           x[1] + 0.3 * x[2] - 0.2 * group[size_t(f)]});
      }
      uv.indices.push_back(it->second);
    }
  m.face_varying = {uv};
  return m;
}

TEST_CASE("Face-varying UVs next to extraordinary vertices and on n-gons: Bfr's face-varying surfaces") {
  struct Case {
    const char* file;
    std::vector<int> group;
  };
  // The cube: two faces in one island, the others alone (valence-3 vertices, seams, corners);
  // the pyramid under Catmull-Clark: triangles (three sub-faces each) and the square.
  for (const Case& c : {Case{"examples/meshes/cube.obj", {0, 0, 1, 2, 3, 4}},
                        Case{"examples/meshes/pyramid.obj", {0, 0, 0, 1, 1}}}) {
    CAPTURE(std::string(c.file));
    const MeshData mesh = with_islands(read_mesh(test::source_path(c.file)), c.group);
    for (FaceVaryingLinear mode : {FaceVaryingLinear::None, FaceVaryingLinear::CornersOnly,
                                   FaceVaryingLinear::CornersPlus1, FaceVaryingLinear::Boundaries,
                                   FaceVaryingLinear::All}) {
      CAPTURE(int(mode));
      const Worst w = compare(mesh, "catmull-clark", mode, false, 60);
      MESSAGE(std::string(c.file), " mode ", std::string(face_varying_linear_name(mode)),
              ": largest distance from Bfr ", w.value,
              ", of derivatives ", w.derivative);
      CHECK(w.value < 1e-12);
      CHECK(w.derivative < 1e-11);
    }
  }
}

TEST_CASE("The face-varying modes give different surfaces (the comparisons with Bfr tell them apart)") {
  const MeshData mesh = bumped_uvs(read_mesh(test::source_path("examples/meshes/textured-tube.obj")));
  auto at = [&](FaceVaryingLinear mode) {
    EvaluateRequest r;
    r.mesh = mesh;
    r.scheme.text = "catmull-clark";
    r.shape.face_varying = mode;
    const std::vector<Index> faces{0, 5, 11};
    const std::vector<double> uv{0.3, 0.4, 0.5, 0.5, 0.1, 0.9};
    return evaluate_face_varying(prepare_evaluation(r), 0, faces, uv, 0).position;
  };
  const std::vector<double> smooth = at(FaceVaryingLinear::None), linear = at(FaceVaryingLinear::All);
  double most = 0;
  for (size_t i = 0; i < smooth.size(); ++i) most = std::max(most, std::fabs(smooth[i] - linear[i]));
  CHECK(most > 1e-3);
}

TEST_CASE("Face-varying UVs on the limit surface: Bfr's face-varying surfaces in every linear interpolation mode") {
  struct Case {
    const char* file;
    const char* scheme;
    bool triangles;
  };
  for (const Case& c : {Case{"examples/meshes/textured-tube.obj", "catmull-clark", false},
                        Case{"examples/meshes/textured-tube-triangles.obj", "loop", true}}) {
    CAPTURE(std::string(c.file));
    const MeshData mesh = bumped_uvs(read_mesh(test::source_path(c.file)));
    for (FaceVaryingLinear mode : {FaceVaryingLinear::None, FaceVaryingLinear::CornersOnly,
                                   FaceVaryingLinear::CornersPlus1, FaceVaryingLinear::CornersPlus2,
                                   FaceVaryingLinear::Boundaries, FaceVaryingLinear::All}) {
      CAPTURE(int(mode));
      const Worst w = compare(mesh, c.scheme, mode, c.triangles, 60);
      MESSAGE(std::string(c.scheme), " mode ", std::string(face_varying_linear_name(mode)),
              ": largest distance from Bfr ", w.value,
              ", of derivatives ", w.derivative);
      CHECK(w.value < 1e-12);
      CHECK(w.derivative < 1e-11);
    }
  }
}

#endif
