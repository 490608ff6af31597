// In face and corner rules n is the face size, as k is (docs/scheme-format.md, "Face rules"):
// a rule written with n must give the same points as the same rule written with k, also
// where a face is larger than every valence of the mesh (the weight tables once reached n
// only up to the largest valence, and a face rule read past their end).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "framework/engine/refiner.h"
#include "framework/scheme/scheme_registry.h"
#include "support/test_meshes.h"
#include "support/scheme_files.h"

using namespace subdiv;
namespace fs = std::filesystem;

namespace {

fs::path write_scheme(const std::string& name, const std::string& text) {
  return test::write_scheme_file("subdivkit-face-rule-tests", name, text);
}

// A hexagonal prism: two hexagons among vertices of valence 3 (faces of 6 > valence 3).
test::Mesh hexagonal_prism() {
  test::Mesh m;
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 6; ++i)
      m.add_vertex(std::cos(i * std::numbers::pi / 3), std::sin(i * std::numbers::pi / 3) + 0.1 * i * i, z + 0.05 * i);
  m.add_face({5, 4, 3, 2, 1, 0});
  m.add_face({6, 7, 8, 9, 10, 11});
  for (Index i = 0; i < 6; ++i) m.add_face({i, Index((i + 1) % 6), Index((i + 1) % 6 + 6), Index(i + 6)});
  return m;
}

std::vector<double> refined_points(const std::string& scheme_file, const test::Mesh& mesh, int levels) {
  const auto scheme = load_scheme(scheme_file);
  RefineOptions options;
  options.levels = levels;
  const Hierarchy h = refine(*scheme, mesh.level(), options);
  return interpolate(h, levels, mesh.positions, 3);
}

}  // namespace

TEST_CASE("a face rule written with n gives the points of the same rule written with k") {
  // Catmull & Clark 1978: the face point is the centroid, 1/k (= 1/n) on each corner.
  auto scheme = [](const std::string& face_weight) {
    return R"({"name": "t", "split": "quad", "curve": "cubic-bspline", "rules": {
      "face": [{"sum": "vertices", "w": ")" + face_weight + R"("}],
      "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
      "vertex": [{"at": "self", "w": "(n-3)/n"}, {"sum": "ring", "w": "2/n^2"},
                 {"sum": "faces", "new": "face", "w": "1/n^2"}]}})";
  };
  const auto by_k = write_scheme("face-by-k", scheme("1/k"));
  const auto by_n = write_scheme("face-by-n", scheme("1/n"));
  for (const test::Mesh& mesh : {test::cube(), hexagonal_prism()}) {
    const auto expected = refined_points(by_k.string(), mesh, 2);
    const auto got = refined_points(by_n.string(), mesh, 2);
    REQUIRE(got.size() == expected.size());
    for (size_t i = 0; i < got.size(); ++i) CHECK(got[i] == expected[i]);
  }
}

TEST_CASE("a corner rule written with n gives the points of the same rule written with k") {
  // Doo & Sabin 1978's corner weights, once over k (schemes/doo-sabin.json) and once over n.
  auto scheme = [](char size) {
    std::string text = R"J({"name": "t", "split": "dual", "faces": "any", "curve": "chaikin", "rules": {
      "corner": [{"sum": "vertices", "w": "j == 0 ? (S + 5)/(4*S) : (3 + 2*cos(2*pi*j/S))/(4*S)"}]}})J";
    std::replace(text.begin(), text.end(), 'S', size);
    return text;
  };
  const auto by_k = write_scheme("corner-by-k", scheme('k'));
  const auto by_n = write_scheme("corner-by-n", scheme('n'));
  const test::Mesh mesh = hexagonal_prism();
  const auto expected = refined_points(by_k.string(), mesh, 2);
  const auto got = refined_points(by_n.string(), mesh, 2);
  REQUIRE(got.size() == expected.size());
  for (size_t i = 0; i < got.size(); ++i) CHECK(got[i] == expected[i]);
  // And k's version is the shipped scheme's.
  const auto shipped = refined_points("doo-sabin", mesh, 2);
  for (size_t i = 0; i < got.size(); ++i) CHECK(shipped[i] == expected[i]);
}
