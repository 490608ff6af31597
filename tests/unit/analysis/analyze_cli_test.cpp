// `subdiv analyze` and `subdiv refine --limit` end to end.
#include <doctest/doctest.h>

#include <complex>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_runner.h"
#include "unit/analysis/surface_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Vertex positions of an OBJ file, in order.
std::vector<double> obj_positions(const std::filesystem::path& p) {
  std::vector<double> out;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    double x, y, z;
    s >> x >> y >> z;
    out.insert(out.end(), {x, y, z});
  }
  return out;
}

}  // namespace

TEST_CASE("subdiv analyze: table, JSON, SVG and characteristic maps for a surface scheme") {
  const auto dir = fresh_dir("analyze-cli");
  const auto r = run_subdiv("analyze catmull-clark --valence 3..5 --json " + (dir / "cc.json").string() + " --svg " +
                            (dir / "cc.svg").string() + " --vtk " + (dir / "maps").string());
  CAPTURE(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("C1 at valence 3") != std::string::npos);
  CHECK(r.output.find("C1 at valence 5") != std::string::npos);
  const auto j = nlohmann::json::parse(slurp(dir / "cc.json"));
  REQUIRE(j["analyses"].size() == 3);
  const double c = std::cos(2 * kPi / 5), A = 1 + c + std::cos(kPi / 5) * std::sqrt(2 * (9 + c));
  CHECK(j["analyses"][2]["lambda1"].get<double>() == doctest::Approx((4 + A) / 16).epsilon(1e-12));
  CHECK(slurp(dir / "cc.svg").find("<svg") != std::string::npos);
  CHECK(std::filesystem::exists(dir / "maps" / "catmull-clark_characteristic_n4.vtp"));
}

TEST_CASE("subdiv analyze --json: a dual crease's own spectrum is Chaikin's") {
  // Doo-Sabin's crease points follow Chaikin's rule (docs/features.md), whose local matrix
  // has the eigenvalues 1, 1/2, 1/4 of the quadratic B-spline (Chaikin 1974), then smaller.
  const auto dir = fresh_dir("analyze-cli-crease");
  const auto r = run_subdiv("analyze doo-sabin --crease --valence 4 --json " + (dir / "ds.json").string());
  CAPTURE(r.output);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(slurp(dir / "ds.json"));
  REQUIRE(j["analyses"].size() == 1);
  REQUIRE(j["crease_analyses"].size() == 1);
  CHECK(j["analyses"][0]["crease_eigenvalues"].empty());  // no crease at an interior face
  const auto& crease = j["crease_analyses"][0]["crease_eigenvalues"];
  REQUIRE(crease.size() > 3);
  // A real eigenvalue is written as a number, a complex one as {"re", "im"}.
  const auto value = [](const nlohmann::json& z) {
    return z.is_number() ? std::complex<double>(z.get<double>(), 0)
                         : std::complex<double>(z["re"].get<double>(), z["im"].get<double>());
  };
  for (size_t k = 0; k < 3; ++k) {
    CHECK(value(crease[k]).real() == doctest::Approx(std::ldexp(1.0, -int(k))).epsilon(1e-9));
    CHECK(std::abs(value(crease[k]).imag()) < 1e-9);
  }
  for (size_t k = 3; k < crease.size(); ++k) CHECK(std::abs(value(crease[k])) <= 0.25 + 1e-9);
}

TEST_CASE("subdiv analyze: parameters, curve schemes, user files, failures") {
  const auto warren = run_subdiv("analyze loop --param beta=warren --valence 4");
  CAPTURE(warren.output);
  CHECK(warren.exit_code == 0);
  CHECK(warren.output.find("0.375") != std::string::npos);  // 3/8 + cos(pi/2)/4

  const auto curve = run_subdiv("analyze four-point");
  CAPTURE(curve.output);
  CHECK(curve.exit_code == 0);
  CHECK(curve.output.find("C1 proven") != std::string::npos);
  CHECK(curve.output.find("eigenvalues: 1, 0.5, 0.25, 0.25, 0.125, -0.0625, -0.0625") != std::string::npos);

  // Kobbelt 1996's variational scheme of the second difference: C2; its local matrix has
  // the eigenvalues 1, 1/2, 1/4 of a C2 scheme, then one of about 0.175 > 1/8, so
  // third derivatives diverge and C3 cannot be proven.
  const auto variational = run_subdiv("analyze variational-cubic");
  CAPTURE(variational.output);
  CHECK(variational.exit_code == 0);
  CHECK(variational.output.find("C2 proven") != std::string::npos);
  CHECK(variational.output.find("C3 not proven") != std::string::npos);
  CHECK(variational.output.find("eigenvalues: 1, 0.5, 0.25,") != std::string::npos);

  const auto file = write_temp("broken-cli.json", R"({"name": "broken", "split": "quad", "faces": "any", "curve": "cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
              "vertex": [{"at": "self", "w": "(n-2)/n + 0.5"}, {"sum": "ring", "w": "1/n^2 - 0.5/n"},
                         {"sum": "faces", "new": "face", "w": "1/n^2"}]}})");
  const auto broken = run_subdiv("analyze " + file.string() + " --valence 5");
  CAPTURE(broken.output);
  CHECK(broken.exit_code == 0);
  CHECK(broken.output.find("fails: lambda_1 != lambda_2") != std::string::npos);

  const auto bad = run_subdiv("analyze catmull-clark --valence 1..4");
  CHECK(bad.exit_code != 0);
  CHECK(bad.output.find("--valence") != std::string::npos);
  // Catmull & Clark's rules hold at interior valence 2 (two quads sharing two edges), so the
  // local subdivision matrix exists and is analysed: 1/4 twice, and -1/4 as large, so no
  // tangent plane (Karciauskas & Peters 2009, "Lens-shaped surfaces and C2 subdivision").
  const auto two = run_subdiv("analyze catmull-clark --valence 2..4");
  CAPTURE(two.output);
  CHECK(two.exit_code == 0);
  CHECK(two.output.find("(lambda_3 = -0.25)") != std::string::npos);
  CHECK(two.output.find("C1 at valence 3") != std::string::npos);
  // A crease through it (both ring edges sharp) leaves one quad a side: each side is a
  // boundary vertex of one face, whose limit follows the crease curve.
  const auto crease = run_subdiv("analyze catmull-clark --valence 2 --crease");
  CAPTURE(crease.output);
  CHECK(crease.exit_code == 0);
  CHECK(crease.output.find("sides of 1 and 1 faces") != std::string::npos);
}

TEST_CASE("subdiv refine --limit: level L and L+1 agree on the old vertices; --levels 0 works") {
  const auto dir = fresh_dir("limit-cli");
  const std::string mesh = source_path("examples/meshes/cube.obj");
  for (int l : {0, 1, 2, 3}) {
    const auto r = run_subdiv("refine " + mesh + " --levels " + std::to_string(l) + " --limit -q -o " +
                              (dir / ("l" + std::to_string(l) + ".obj")).string());
    CAPTURE(r.output);
    REQUIRE(r.exit_code == 0);
  }
  for (int l : {0, 1, 2}) {
    CAPTURE(l);
    const auto a = obj_positions(dir / ("l" + std::to_string(l) + ".obj"));
    const auto b = obj_positions(dir / ("l" + std::to_string(l + 1) + ".obj"));
    REQUIRE(b.size() > a.size());
    // Quad splits number the children of old vertices first, in order.
    for (size_t i = 0; i < a.size(); ++i) CHECK(std::abs(a[i] - b[i]) < 1e-12);
  }
  // --levels 0: the control cube's corners go to (9 v + 4 sum e + sum f)/24 (Halstead, Kass & DeRose 1993).
  const auto zero = obj_positions(dir / "l0.obj");
  const auto input = obj_positions(mesh);
  REQUIRE(zero.size() == input.size());
  double lo = 1e9, hi = -1e9;
  for (double x : input) lo = std::min(lo, x), hi = std::max(hi, x);
  for (double x : zero) CHECK((std::abs(x - (lo + (hi - lo) / 4)) < 1e-12 || std::abs(x - (hi - (hi - lo) / 4)) < 1e-12));
  // .vtp output carries the normals.
  const auto v = run_subdiv("refine " + mesh + " --levels 2 --limit -q -o " + (dir / "cube.vtp").string());
  CHECK(v.exit_code == 0);
  const std::string text = slurp(dir / "cube.vtp");
  CHECK(text.find("Name=\"normal\"") != std::string::npos);
  CHECK(text.find("NumberOfComponents=\"3\"") != std::string::npos);
}
