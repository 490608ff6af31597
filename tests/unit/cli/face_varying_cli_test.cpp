// UVs with seams through `subdiv refine`: an OBJ whose texture coordinates are cut along a
// column of the grid. The refined OBJ must keep the cut (corners on the two sides of the
// seam use different vt, corners on one side share them) and its vt must be the
// bilinear UVs (OpenSubdiv's default mode "all" is linear in each face, and these UVs are
// affine per side); the .vtp must have a point per side of the seam with the UVs as its
// active texture coordinates.
#include <doctest/doctest.h>

#include <fstream>
#include <map>
#include <set>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "framework/io/mesh_read.h"
#include "support/cli_checks.h"
#include "support/cli_runner.h"
#include "support/scheme_files.h"
#include "support/vtk_read.h"

using namespace subdiv;
using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

// A 4 x 2 grid of unit quads (with `triangles`, each cut along a diagonal); UVs (x, y) left
// of x = 2, (x + 1, y) right of it.
void write_seamed_grid(const fs::path& file, bool triangles = false) {
  std::ofstream out(file);
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 4; ++i) out << "v " << i << " " << j << " 0\n";
  std::map<std::pair<int, int>, int> vt;  // (vertex, side) -> vt number
  auto uv = [&](int v, int side) {
    auto [it, added] = vt.emplace(std::pair(v, side), int(vt.size()) + 1);
    if (added) out << "vt " << (v % 5) + side << " " << (v / 5) << "\n";
    return it->second;
  };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      const int side = i >= 2 ? 1 : 0, v = j * 5 + i;
      const int corners[4] = {v, v + 1, v + 6, v + 5};
      int t[4];
      for (int k = 0; k < 4; ++k) t[k] = uv(corners[k], side);
      auto face = [&](std::initializer_list<int> ks) {
        out << "f";
        for (int k : ks) out << " " << corners[k] + 1 << "/" << t[k];
        out << "\n";
      };
      if (triangles) face({0, 1, 2}), face({0, 2, 3});
      else face({0, 1, 2, 3});
    }
}

}  // namespace

TEST_CASE("an OBJ with a UV seam: the refined OBJ keeps the seam and the bilinear UVs; the .vtp splits the points") {
  const auto dir = fresh_dir("cli-fvar");
  write_seamed_grid(dir / "grid.obj");
  const CliResult r = run_subdiv("refine " + (dir / "grid.obj").string() + " --scheme catmull-clark -l 2 -o " +
                                 (dir / "out.obj").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  const MeshData m = read_mesh(dir / "out.obj");
  REQUIRE(m.face_varying.size() == 1);
  const FaceVaryingArray& uv = m.face_varying[0];
  CHECK(uv.role == ArrayRole::TextureCoordinates);
  CHECK(m.options.fvar_interpolate_boundary == 5);  // the mode used, written back as OpenSubdiv's tag
  // Per face: its side (centroid left or right of x = 2); per vertex and side: one vt.
  std::map<std::pair<Index, int>, Index> vt_of;
  for (Index f = 0; f + 1 < Index(m.face_offsets.size()); ++f) {
    double cx = 0;
    for (Index c = m.face_offsets[f]; c < m.face_offsets[f + 1]; ++c) cx += m.positions[3 * m.face_vertices[c]];
    const int side = cx / (m.face_offsets[f + 1] - m.face_offsets[f]) > 2 ? 1 : 0;
    for (Index c = m.face_offsets[f]; c < m.face_offsets[f + 1]; ++c) {
      const Index v = m.face_vertices[c], t = uv.indices[c];
      auto [it, added] = vt_of.emplace(std::pair(v, side), t);
      CHECK(it->second == t);  // one vt per vertex and side
      // Bilinear UVs of affine data: exactly the position, shifted by one on the right.
      CHECK(uv.values[2 * t] == doctest::Approx(m.positions[3 * v] + side).epsilon(1e-12));
      CHECK(uv.values[2 * t + 1] == doctest::Approx(m.positions[3 * v + 1]).epsilon(1e-12));
    }
  }
  int seam_vertices = 0;
  for (const auto& [key, t] : vt_of)
    if (key.second == 0 && vt_of.count({key.first, 1})) {
      CHECK(vt_of.at({key.first, 1}) != t);  // the two sides of the seam use different vt
      ++seam_vertices;
    }
  CHECK(seam_vertices == 2 * 4 + 1);  // the column x = 2 after two levels: 9 vertices

  const CliResult v = run_subdiv("refine " + (dir / "grid.obj").string() + " --scheme catmull-clark -l 2 -o " +
                                 (dir / "out.vtp").string());
  REQUIRE_MESSAGE(v.exit_code == 0, v.output);
  const auto poly = read_vtp(dir / "out.vtp");
  CHECK(poly->GetNumberOfPoints() == 17 * 9 + seam_vertices);  // (4*4+1) x (2*4+1) vertices, the seam twice
  REQUIRE(poly->GetPointData()->GetTCoords());
  REQUIRE(poly->GetPointData()->GetArray("vertex_id"));
}

TEST_CASE("--fvar-boundary is checked, and a vt number out of range is refused with its line") {
  const auto dir = fresh_dir("cli-fvar-bad");
  write_seamed_grid(dir / "grid.obj");
  check_refused("refine " + (dir / "grid.obj").string() + " --fvar-boundary sideways", dir / "o.obj", "--fvar-boundary");
  std::ofstream(dir / "bad.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/7\n";
  check_refused("refine " + (dir / "bad.obj").string() + " --scheme loop", dir / "o.obj", "bad.obj:5: this face uses vt number 7");
}

TEST_CASE("a scheme without boundary rules refines a closed mesh, and names the UVs when their seams need them") {
  // Catmull-Clark's rules without a "curve": the closed cube refines; with UVs, whose seams
  // refine as boundaries, the refusal names the array and the two ways out.
  const auto dir = fresh_dir("cli-fvar-no-curve");
  const auto scheme = write_scheme_file("cli-fvar-no-curve", "cc-no-curve", R"({"name": "cc-no-curve", "split": "quad",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
              "vertex": [{"at": "self", "w": "(n-2)/n"}, {"sum": "ring", "w": "1/n^2"},
                         {"sum": "faces", "new": "face", "w": "1/n^2"}]}})");
  std::ofstream(dir / "cube.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                     "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  std::ofstream(dir / "cube-uv.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                        "f 1/1 4/2 3/3 2/4\nf 5/1 6/2 7/3 8/4\nf 1/1 2/2 6/3 5/4\nf 2/1 3/2 7/3 6/4\n"
                                        "f 3/1 4/2 8/3 7/4\nf 4/1 1/2 5/3 8/4\n";
  const CliResult plain = run_subdiv("refine " + (dir / "cube.obj").string() + " -s " + scheme.string() + " -l 2 -o " +
                              (dir / "plain.obj").string());
  CHECK_MESSAGE(plain.exit_code == 0, plain.output);
  check_refused("refine " + (dir / "cube-uv.obj").string() + " -s " + scheme.string() + " -l 2",
                dir / "uv.obj", "face-varying array 'uv' (UVs: OBJ vt)");
  const CliResult r = run_subdiv("refine " + (dir / "cube-uv.obj").string() + " -s " + scheme.string() + " -l 2 -o " +
                          (dir / "uv.obj").string());
  CHECK(r.output.find("give the scheme a \"curve\", or remove the array") != std::string::npos);
}

TEST_CASE("sqrt3 and mid-edge refine UVs with a seam: every vt is one side's UV map at its point") {
  // Both splits make faces across the seam (docs/primvars.md, "Which splits"); each corner
  // takes its value on one side. Mid-edge points are edge midpoints, so the affine UVs stay
  // exactly (x, y) or (x + 1, y). sqrt3 in the default mode "all" keeps old values and puts
  // face points at their face's centroid, which is where the face point is; the old
  // vertices of this flat grid stay too (each ring is centrally symmetric, boundaries wait
  // in the first step), so the same holds.
  const auto dir = fresh_dir("cli-fvar-crossing");
  write_seamed_grid(dir / "quads.obj");
  write_seamed_grid(dir / "triangles.obj", true);
  for (const auto& scheme_and_input : {std::pair<std::string, std::string>{"mid-edge", "quads.obj"},
                                       std::pair<std::string, std::string>{"sqrt3", "triangles.obj"}}) {
    // Named copies: doctest's CHECK_MESSAGE captures them in a lambda, which clang does not
    // allow for structured bindings.
    const std::string scheme = scheme_and_input.first, input = scheme_and_input.second;
    const CliResult r = run_subdiv("refine " + (dir / input).string() + " --scheme " + scheme + " -l 1 -o " +
                                   (dir / "out.obj").string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    const MeshData m = read_mesh(dir / "out.obj");
    REQUIRE(m.face_varying.size() == 1);
    const FaceVaryingArray& uv = m.face_varying[0];
    std::set<int> sides;
    for (size_t c = 0; c < m.face_vertices.size(); ++c) {
      const Index v = m.face_vertices[c], t = uv.indices[c];
      const double x = m.positions[3 * v], y = m.positions[3 * v + 1];
      const int side = std::abs(uv.values[2 * t] - x) < 1e-9 ? 0 : std::abs(uv.values[2 * t] - x - 1) < 1e-9 ? 1 : -1;
      CHECK_MESSAGE(side >= 0, scheme, ": vt ", t, " (", uv.values[2 * t], ") at x = ", x);
      CHECK(uv.values[2 * t + 1] == doctest::Approx(y).epsilon(1e-9));
      sides.insert(side);
    }
    CHECK(sides.size() == 2);
  }
}
