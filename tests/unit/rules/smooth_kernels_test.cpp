// The compiled smooth kernels (rules/smooth_kernels.h) compute smooth interior points in
// step_values without building rows. They must give the generic rule interpreter's values
// to round-off for every shipped surface scheme, on meshes with every context the rules
// know (boundaries, creases, corners, darts, fractional sharpness, valences 3-12, faces of
// 3-8 sides), must actually take the smooth interior points, and must give the same bits
// on any thread count.
#include <algorithm>
#include <cmath>
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <unistd.h>

#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

struct Case {
  std::string name;
  Level level;
  std::vector<double> positions;
};

Case of(const std::string& name, const Mesh& m) { return {name, m.level(), m.positions}; }

// A closed prism over a regular k-gon: two k-sided caps and k quads, every vertex of valence 3.
Mesh prism(int k) {
  Mesh m;
  const double pi = std::acos(-1.0);
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < k; ++i) m.add_vertex(std::cos(2 * pi * i / k), std::sin(2 * pi * i / k), z + 0.1 * i);
  std::vector<Index> bottom, top;
  for (int i = 0; i < k; ++i) bottom.push_back(Index(k - 1 - i)), top.push_back(Index(k + i));
  m.corners.insert(m.corners.end(), bottom.begin(), bottom.end()), m.offsets.push_back(Index(m.corners.size()));
  m.corners.insert(m.corners.end(), top.begin(), top.end()), m.offsets.push_back(Index(m.corners.size()));
  for (int i = 0; i < k; ++i) {
    const Index j = Index((i + 1) % k);
    m.add_face({Index(i), j, Index(k + j), Index(k + i)});
  }
  return m;
}

// Sharp, semi-sharp and fractional edges (whose ends are darts unless they meet) and a
// sharp vertex (a corner), spread over the mesh.
Case with_features(Case c) {
  c.name += " with features";
  const Index edges = c.level.edge_count();
  c.level.edge_sharpness.assign(size_t(edges), 0.f);
  c.level.edge_sharpness[0] = 10.f;
  c.level.edge_sharpness[size_t(edges / 3)] = 1.5f;
  c.level.edge_sharpness[size_t(2 * edges / 3)] = 0.5f;
  c.level.vertex_sharpness.assign(size_t(c.level.vertex_count), 0.f);
  c.level.vertex_sharpness[size_t(c.level.vertex_count / 2)] = 2.f;
  return c;
}

// All quads with extraordinary vertices of valence 3 to 12: one Catmull-Clark level of
// polygon meshes.
Case quads_from(const std::string& name, const Mesh& m) {
  const auto scheme = load_scheme("catmull-clark");
  RefineOptions o;
  o.levels = 1;
  const Hierarchy h = refine(*scheme, m.level(), o);
  return {name + " refined to quads", h.levels[1], interpolate(h, 1, m.positions, 3)};
}

std::vector<Case> meshes_for(int required_face_size) {
  std::vector<Case> cases;
  if (required_face_size == 3) {
    for (int n = 3; n <= 12; ++n) cases.push_back(of("bipyramid " + std::to_string(n), bipyramid(n)));
    cases.push_back(of("octahedron", octahedron()));
    cases.push_back(of("triangle grid", grid(4, 3, true)));
    cases.push_back(with_features(of("triangle torus", torus(6, 5, true))));
    cases.push_back(with_features(of("triangle grid", grid(5, 4, true))));
    return cases;
  }
  if (required_face_size == 4) {
    cases.push_back(quads_from("bipyramid 12", bipyramid(12)));
    cases.push_back(quads_from("prism 7", prism(7)));
    cases.push_back(of("grid", grid(4, 3)));
    cases.push_back(with_features(of("torus", torus(6, 5))));
    cases.push_back(with_features(of("cube", cube())));
    return cases;
  }
  for (int k = 3; k <= 8; ++k) cases.push_back(of("prism " + std::to_string(k), prism(k)));
  cases.push_back(of("bipyramid 12", bipyramid(12)));
  cases.push_back(of("pyramid", pyramid()));
  cases.push_back(of("grid", grid(4, 3)));
  cases.push_back(with_features(of("torus", torus(6, 5))));
  cases.push_back(with_features(of("prism 8", prism(8))));
  return cases;
}

// Surface schemes among the shipped files (curve schemes refine polylines).
std::vector<std::string> shipped_surface_schemes() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SUBDIV_SOURCE_DIR) + "/schemes")) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "scheme.schema.json") continue;
    std::ifstream in(entry.path());
    if (nlohmann::json::parse(in).value("kind", "surface") == "curve") continue;
    names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct Run {
  std::vector<std::vector<double>> levels;  // values after each step
  std::int64_t kernel = 0, plan = 0, generic = 0, flat = 0;
};

// `levels` steps of step_values, with the kernels (and plans) or with the interpreter alone.
Run run(const Scheme& scheme, const Case& c, int levels, bool kernels) {
  RefineOptions o;
  o.levels = levels;
  o.evaluation.use_kernels = kernels;
  o.evaluation.use_row_plans = kernels;
  RowPaths paths;
  o.evaluation.row_paths = &paths;
  const Hierarchy h = refine_topology(scheme, c.level, o);
  Run r;
  std::vector<double> values = c.positions;
  for (int l = 0; l < levels; ++l) r.levels.push_back(values = step_values(scheme, h, l, values, 3, o));
  r.kernel = paths.kernel, r.plan = paths.plan, r.generic = paths.generic, r.flat = paths.flat;
  return r;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]) / std::max(1.0, std::abs(b[i])));
  return worst;
}

}  // namespace

TEST_CASE("the smooth kernels give the rule interpreter's values for every shipped surface scheme") {
  for (const std::string& name : shipped_surface_schemes()) {
    CAPTURE(name);
    const auto scheme = load_scheme(name);
    int compared = 0;
    for (const Case& c : meshes_for(scheme->required_face_size)) {
      CAPTURE(c.name);
      Run fast, generic;
      try {
        generic = run(*scheme, c, 2, false);
      } catch (const Error&) {
        continue;  // a mesh the scheme refuses (its message is tested elsewhere)
      }
      fast = run(*scheme, c, 2, true);
      for (size_t l = 0; l < fast.levels.size(); ++l) {
        CAPTURE(l);
        REQUIRE(fast.levels[l].size() == generic.levels[l].size());
        CHECK(largest_difference(fast.levels[l], generic.levels[l]) < 1e-13);
      }
      CHECK(generic.kernel == 0);
      CHECK(fast.kernel + fast.plan + fast.generic == generic.generic);
      ++compared;
    }
    CHECK(compared > 0);
  }
}

TEST_CASE("the kernels take every point of a closed smooth mesh, and leave features to the interpreter") {
  struct Expect {
    const char* scheme;
    Case mesh;
  };
  const std::vector<Expect> all_smooth = {{"catmull-clark", of("torus", torus(8, 6))},
                                          {"catmull-clark", of("prism 5", prism(5))},
                                          {"loop", of("triangle torus", torus(8, 6, true))},
                                          {"butterfly", of("triangle torus", torus(8, 6, true))},
                                          {"modified-butterfly", of("triangle torus", torus(8, 6, true))},
                                          {"doo-sabin", of("torus", torus(8, 6))},
                                          {"bilinear", of("torus", torus(8, 6))}};
  for (const Expect& e : all_smooth) {
    CAPTURE(e.scheme);
    CAPTURE(e.mesh.name);
    const Run r = run(*load_scheme(e.scheme), e.mesh, 2, true);
    CHECK(r.kernel > 0);
    CHECK(r.plan == 0);
    CHECK(r.generic == 0);
  }
  // Features and boundaries: the elements on them go the generic way, the rest by kernel.
  for (const Case& c : {with_features(of("torus", torus(8, 6))), of("grid", grid(6, 5))}) {
    CAPTURE(c.name);
    const Run r = run(*load_scheme("catmull-clark"), c, 1, true);
    CHECK(r.kernel > 0);
    CHECK(r.plan + r.generic > 0);
  }
}

// Also on meshes with boundaries, whose boundary rows make the step classify the level's
// features on first use, from whichever thread gets there first (refiner.cpp, prepare_step).
TEST_CASE("the kernels give the same bits on one thread and on two") {
  for (const auto& case_ : {std::pair{"loop", torus(300, 200, true)}, std::pair{"doo-sabin", torus(300, 200)},
                            std::pair{"catmull-clark", torus(300, 200)}, std::pair{"catmull-clark", grid(300, 200)},
                            std::pair{"loop", grid(300, 200, true)}, std::pair{"doo-sabin", grid(300, 200)}}) {
    const auto& [name, mesh] = case_;
    const std::string scheme_name = name;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
    CAPTURE(scheme_name);
    const auto scheme = load_scheme(name);
    RefineOptions o;
    o.levels = 1;
    const Hierarchy h = refine_topology(*scheme, mesh.level(), o);
    std::vector<double> one, two;
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
      one = step_values(*scheme, h, 0, mesh.positions, 3, o);
    }
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
      two = step_values(*scheme, h, 0, mesh.positions, 3, o);
    }
    CHECK(one == two);
  }
}

// A weight that reads the face size k of the face point it weighs (element_rules.cpp passes
// each face's own k): on quads this scheme is Catmull-Clark, so kernels, interpreter and the
// shipped file must agree.
TEST_CASE("the kernels weigh an edge's face points by their own face's size") {
  const auto path = std::filesystem::temp_directory_path() / "subdivkit-kernels-k-weighted.json";
  std::ofstream(path) << R"({"name": "k-weighted", "split": "quad", "faces": "any", "curve": "cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": "1/4"}, {"sum": "faces", "new": "face", "w": "1/k"}],
              "vertex": [{"at": "self", "w": "(n-2)/n"}, {"sum": "ring", "w": "1/n^2"},
                         {"sum": "faces", "new": "face", "w": "1/n^2"}]}})";
  const Case c = of("torus", torus(6, 5));
  const Run k_weighted = run(*load_scheme(path.string()), c, 2, true);
  const Run interpreter = run(*load_scheme(path.string()), c, 2, false);
  const Run shipped = run(*load_scheme("catmull-clark"), c, 2, true);
  CHECK(k_weighted.kernel > 0);
  for (size_t l = 0; l < 2; ++l) {
    CHECK(largest_difference(k_weighted.levels[l], interpreter.levels[l]) < 1e-13);
    CHECK(largest_difference(k_weighted.levels[l], shipped.levels[l]) < 1e-13);
  }
  std::filesystem::remove(path);
}

// The flat kernels (rules/flat_kernels.h) take the rules whose shape they know: every smooth
// interior point of Catmull-Clark, Loop and Doo-Sabin (whose corner weights vary along the
// face), none of the butterflies' edges (far wings). Their values are checked against the
// interpreter's by the first test case (every shipped scheme); here, that they are the path
// actually taken.
TEST_CASE("the flat kernels take Catmull-Clark's, Loop's and Doo-Sabin's smooth points, and only rules of their shapes") {
  for (const auto& [name, mesh] : {std::pair{"catmull-clark", of("torus", torus(8, 6))},
                                   std::pair{"catmull-clark", of("prism 5", prism(5))},
                                   std::pair{"loop", of("triangle torus", torus(8, 6, true))},
                                   std::pair{"doo-sabin", of("torus", torus(8, 6))},
                                   std::pair{"doo-sabin", of("prism 7", prism(7))}}) {
    const std::string scheme_name = name;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
    CAPTURE(scheme_name);
    const Run r = run(*load_scheme(name), mesh, 2, true);
    CHECK(r.kernel > 0);
    CHECK(r.flat == r.kernel);
    CHECK(r.plan + r.generic == 0);  // faces larger than every valence (the prisms' caps) too
  }
  // The butterfly's vertices stay where they are (the flat vertex shape, weight 1) and its
  // edges read far wings (not a flat shape).
  const Case triangles = of("triangle torus", torus(8, 6, true));
  const Run butterfly = run(*load_scheme("butterfly"), triangles, 1, true);
  CHECK(butterfly.flat > 0);
  CHECK(butterfly.flat < butterfly.kernel);
}

// Catmull-Clark's smooth rules written another way: a weight split over two terms that
// gather the same points (the flat kernels merge them), an edge weight that reads n (2 for
// an edge), a vertex that reads its edges' new points instead of its faces' (each interior
// edge point is (v + r_j + f_j-1 + f_j) / 4, so 2/n^2 of their sum and (2n-5)/(2n) of v give
// the same point). Flat kernels and interpreter must agree on meshes with boundaries, creases
// and pentagons among valence-3 vertices; on smooth closed meshes the shipped file too (at a
// dart the edge point of the crease edge is not the smooth one, so there the rules differ).
TEST_CASE("the flat kernels merge terms and read n as the rules do") {
  const auto path = std::filesystem::temp_directory_path() / ("subdivkit-flat-kernels-" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << R"json({"name": "catmull-clark-rewritten", "split": "quad", "faces": "any", "curve": "cubic-bspline",
    "rules": {"face": [{"sum": "vertices", "w": "1/k"}],
              "edge": [{"sum": "ends", "w": "n/16"}, {"sum": "ends", "w": "1/8"}, {"sum": "faces", "new": "face", "w": "1/4"}],
              "vertex": [{"at": "self", "w": "(2*n-5)/(2*n)"}, {"sum": "ring", "w": "1/(4*n^2)"},
                         {"sum": "ring", "w": "1/(4*n^2)"}, {"sum": "edges", "new": "edge", "w": "2/n^2"}]}})json";
  const auto rewritten = load_scheme(path.string());
  const auto shipped = load_scheme("catmull-clark");
  for (const Case& c : {of("torus", torus(6, 5)), of("prism 5", prism(5)), with_features(of("torus", torus(6, 5))),
                        of("grid", grid(5, 4))}) {
    CAPTURE(c.name);
    const Run flat = run(*rewritten, c, 2, true);
    const Run interpreter = run(*rewritten, c, 2, false);
    CHECK(flat.flat > 0);
    const bool closed_smooth = c.name == "torus" || c.name == "prism 5";
    const Run reference = closed_smooth ? run(*shipped, c, 2, true) : Run{};
    for (size_t l = 0; l < 2; ++l) {
      CHECK(largest_difference(flat.levels[l], interpreter.levels[l]) < 1e-13);
      if (closed_smooth) CHECK(largest_difference(flat.levels[l], reference.levels[l]) < 1e-13);
    }
  }
  std::filesystem::remove(path);
}
