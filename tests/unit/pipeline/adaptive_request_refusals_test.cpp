// What adaptive refinement (framework/pipeline/adaptive_request.h) does not do is refused
// with the option's name and the way out, never ignored: per-vertex scheme parameters (the
// stages take one value for the whole mesh) and limit normals (an adaptive mesh has none).
// Ignored, a per-vertex lambda of catmull-clark-shape gave the default shape without a word.
#include <doctest/doctest.h>

#include <string>

#include "framework/pipeline/adaptive_request.h"
#include "framework/util/option_spelling.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

AdaptiveRequest cube_request(const std::string& scheme) {
  AdaptiveRequest r;
  r.refine.mesh = test::mesh_data(test::cube());
  r.refine.mesh_name = "cube";
  r.refine.scheme.text = scheme;
  r.refine.levels = 2;
  return r;
}

// The message the request's option names spell, as a front-end would (`--vertex-param`).
std::string refusal(AdaptiveRequest r) {
  try {
    refine_adaptive_request(std::move(r));
  } catch (const OptionError& e) {
    return e.spelled({{"vertex_param", "--vertex-param"}, {"param", "--param"}, {"normals", "--normals"},
                      {"limit", "--limit"}});
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("adaptive refinement refuses per-vertex scheme parameters, given or from files") {
  AdaptiveRequest given = cube_request("catmull-clark-shape");
  given.refine.vertex_parameters["lambda"] = std::vector<double>(8, 1.0);
  const std::string message = refusal(std::move(given));
  CHECK(contains(message, "--vertex-param"));
  CHECK(contains(message, "per vertex"));
  CHECK(contains(message, "--param"));

  AdaptiveRequest from_file = cube_request("catmull-clark-shape");
  from_file.refine.vertex_parameter_files["lambda"] = "lambda.txt";  // refused before it is read
  CHECK(contains(refusal(std::move(from_file)), "--vertex-param"));

  // A parameter for the whole mesh is taken.
  AdaptiveRequest whole = cube_request("catmull-clark-shape");
  whole.refine.scheme.parameters["lambda"] = "1";
  CHECK(refine_adaptive_request(std::move(whole)).mesh.positions.size() > 0);
}

TEST_CASE("adaptive refinement refuses limit normals and names --limit instead") {
  AdaptiveRequest r = cube_request("catmull-clark");
  r.refine.limit_normals = true;
  const std::string message = refusal(std::move(r));
  CHECK(contains(message, "--normals: adaptive refinement writes no limit normals"));
  CHECK(contains(message, "--limit"));
}

}  // namespace subdiv
