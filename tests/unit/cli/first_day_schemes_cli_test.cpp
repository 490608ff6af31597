// Schemes as a first-day author writes them (copies of the shipped files with a mistake),
// through `subdiv evaluate` and `subdiv refine --adaptive`: what the limit layer cannot do is
// refused with the reason and with the nearest thing the user can run instead, naming the
// scheme as `-s` takes it, and no output file is left.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "support/cli_runner.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

const std::string kCube = source_path("examples/meshes/cube.obj");

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// schemes/catmull-clark.json without its parameter, with the vertex rule's weights of the
// vertex, each ring neighbour and each new face point.
fs::path write_quad_scheme(const fs::path& dir, const std::string& name, const std::string& self,
                           const std::string& ring, const std::string& faces) {
  const fs::path file = dir / (name + ".json");
  std::ofstream(file) << R"({"name": ")" << name << R"(", "split": "quad", "faces": "any", "curve": "cubic-bspline",
  "rules": {
    "face": [{"sum": "vertices", "w": "1/k"}],
    "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/4"}],
    "vertex": [{"at": "self", "w": ")" << self << R"("}, {"sum": "ring", "w": ")" << ring
                      << R"("}, {"sum": "faces", "new": "face", "w": ")" << faces << R"("}]
  }})";
  return file;
}

// `subdiv evaluate` of the cube under `scheme` at (face 0, 0.5, 0.5) into dir/out.csv.
CliResult evaluate_centre(const fs::path& dir, const fs::path& scheme, const std::string& more = "") {
  std::ofstream(dir / "points.csv") << "face,u,v\n0,0.5,0.5\n";
  return run_subdiv_with_prefix("timeout 120 ", "evaluate " + kCube + " -s " + scheme.string() + " --at " +
                                                    (dir / "points.csv").string() + " -o " + (dir / "out.csv").string() +
                                                    more);
}

}  // namespace

TEST_CASE("evaluate: a non-stationary scheme is refused with the reason and `subdiv refine` to run instead") {
  const auto dir = fresh_dir("first-day-nonstationary");
  const fs::path scheme = write_quad_scheme(dir, "tension", "(n-2)/n + 0.1/(l+1)", "1/n^2 - 0.1/(l+1)/n", "1/n^2");
  const fs::path out = dir / "out.csv";
  const auto r = evaluate_centre(dir, scheme);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "is non-stationary"));
  CHECK(contains(r.output, "`subdiv refine MESH -s " + scheme.string() + " -l L`"));
  CHECK(contains(r.output, "-s " + scheme.string() + ":K,STATIONARY"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("evaluate: a scheme that is not C1 is refused when derivatives are asked for, evaluated without them") {
  const auto dir = fresh_dir("first-day-not-c1");
  // A vertex rule that keeps 0.9 of the vertex: valence-4 eigenvalues 0.569 and 0.5.
  const fs::path scheme = write_quad_scheme(dir, "stiff", "0.9", "0.05/n", "0.05/n");
  const fs::path out = dir / "out.csv";
  const auto r = evaluate_centre(dir, scheme);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "scheme 'stiff' is not C1"));
  CHECK(std::regex_search(r.output, std::regex("subdominant eigenvalues are 0\\.569\\d*, 0\\.5")));
  CHECK(contains(r.output, "`subdiv analyze " + scheme.string() + "`"));
  CHECK(contains(r.output, "--derivatives 0"));
  CHECK_FALSE(fs::exists(out));
  const auto positions = evaluate_centre(dir, scheme, " --derivatives 0");
  CHECK(positions.exit_code == 0);
  CHECK(fs::exists(out));
  const auto samples = run_subdiv("evaluate " + kCube + " -s " + scheme.string() + " --samples 2 -o " +
                                  (dir / "s.vtp").string());
  CHECK(samples.exit_code == 1);
  CHECK(contains(samples.output, "no derivatives or normals"));
  CHECK_FALSE(fs::exists(dir / "s.vtp"));
}

TEST_CASE("refine and evaluate --adaptive: splits it cannot refine adaptively are refused with `subdiv refine -l`") {
  const auto dir = fresh_dir("first-day-adaptive");
  fs::copy_file(source_path("schemes/doo-sabin.json"), dir / "my-dual.json");
  const std::string octahedron = source_path("examples/meshes/octahedron.obj");
  const std::string own = (dir / "my-dual.json").string();
  const struct {
    std::string mesh, scheme, advice;
  } cases[] = {{kCube, own, "`subdiv refine MESH -s " + own + " -l 3`"},
               {octahedron, "sqrt3", "`subdiv refine MESH -s sqrt3 -l 3`"},
               {kCube, "mid-edge", "`subdiv refine MESH -s mid-edge -l 3`"}};
  for (const auto& c : cases) {
    for (const std::string command : {"refine", "evaluate"}) {
      CAPTURE(c.scheme);
      CAPTURE(command);
      const fs::path out = dir / "a.vtp";
      const auto r = run_subdiv(command + " " + c.mesh + " -s " + c.scheme + " --adaptive 3 -o " + out.string());
      CHECK(r.exit_code == 1);
      CHECK(contains(r.output, "binary quad and triangle splits only so far"));
      CHECK(contains(r.output, c.advice));
      CHECK_FALSE(fs::exists(out));
    }
  }
}

TEST_CASE("evaluate: a scheme that does not converge is refused with the reason and `subdiv analyze`") {
  const auto dir = fresh_dir("first-day-divergent");
  // Affine (3 - 1 - 1 = 1), so `subdiv validate` passes it; its local subdivision matrix has
  // an eigenvalue 2.4 > 1, so the levels run away.
  const fs::path scheme = write_quad_scheme(dir, "runaway", "3", "-1/n", "-1/n");
  const fs::path out = dir / "out.csv";
  const auto r = evaluate_centre(dir, scheme);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "scheme 'runaway' does not converge"));
  CHECK(contains(r.output, "lambda_0 = 1 is not the simple dominant eigenvalue"));
  CHECK(contains(r.output, "`subdiv analyze " + scheme.string() + "`"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("refine --normals with a scheme that is not C1 is refused; --limit moves the points and leaves the normals out") {
  const auto dir = fresh_dir("first-day-not-c1-refine");
  const fs::path scheme = write_quad_scheme(dir, "stiff", "0.9", "0.05/n", "0.05/n");
  const fs::path out = dir / "out.vtp";
  const auto normals = run_subdiv("refine " + kCube + " -s " + scheme.string() + " -l 1 --normals -o " + out.string());
  CHECK(normals.exit_code == 1);
  CHECK_MESSAGE(contains(normals.output, kCube + ": scheme 'stiff' is not C1, so its limit has no derivatives or normals: at a "
                                         "regular vertex its subdominant eigenvalues are 0.569"),
                normals.output);
  CHECK(contains(normals.output, "`subdiv analyze " + scheme.string() + "`"));
  CHECK(contains(normals.output, "leave out --normals (--limit alone moves the points to their limits)"));
  CHECK_FALSE(fs::exists(out));
  const auto limit = run_subdiv("refine " + kCube + " -s " + scheme.string() + " -l 1 --limit -o " + out.string());
  CHECK_MESSAGE(limit.exit_code == 0, limit.output);
  CHECK(contains(limit.output, "subdiv: warning: scheme 'stiff' is not C1"));
  CHECK(contains(limit.output, "the point data 'normal' and 'normal_exact' are left out"));
  std::ifstream in(out);
  const std::string vtp{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  CHECK_FALSE(contains(vtp, "Name=\"normal\""));
  CHECK(contains(vtp, "Name=\"limit_exact\""));
}

TEST_CASE("refine --limit and --normals with the shipped surface schemes: normals written, no warning") {
  const auto dir = fresh_dir("first-day-shipped-normals");
  const std::string tri = source_path("examples/meshes/octahedron.obj");
  for (const auto& scheme_mesh : {std::pair{"catmull-clark", kCube}, std::pair{"loop", tri}, std::pair{"butterfly", tri},
                                  std::pair{"modified-butterfly", tri}, std::pair{"doo-sabin", kCube},
                                  std::pair{"sqrt3", tri}, std::pair{"interpolating-sqrt3", tri},
                                  std::pair{"mid-edge", kCube}, std::pair{"bilinear", kCube},
                                  std::pair{"quad-bspline", kCube}, std::pair{"loop-composite", tri}}) {
    CAPTURE(scheme_mesh.first);
    const fs::path out = dir / (std::string(scheme_mesh.first) + ".vtp");
    const auto r = run_subdiv("refine " + scheme_mesh.second + " -s " + scheme_mesh.first + " -l 2 --limit -o " +
                              out.string());
    CHECK_MESSAGE(r.exit_code == 0, r.output);
    CHECK_FALSE(contains(r.output, "not C1"));
    std::ifstream in(out);
    const std::string vtp{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    CHECK(contains(vtp, "Name=\"normal\""));
  }
}
