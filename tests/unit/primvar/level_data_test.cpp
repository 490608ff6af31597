// The user's data through a refinement (framework/primvar/level_data.h), checked against
// what must hold whatever the scheme: vertex-varying data is refined exactly as positions
// are (the engine is linear: each channel alone, refined as if it were a coordinate, gives
// the same numbers); affine functions of the position stay the same affine functions
// (every row is affine); integer labels and cell values are inherited, never mixed.
#include <cmath>
#include <doctest/doctest.h>

#include "framework/primvar/level_data.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/refine_helpers.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

// A mesh each surface scheme accepts: closed triangles for triangle schemes, quads else.
Mesh mesh_for(const Scheme& s) {
  const SplitterInfo& info = splitter_info(s.split());
  const bool triangles = s.required_face_size == 3 || info.required_face_size == 3;
  return torus(6, 5, triangles);
}

// Seven channels per vertex, none of them a coordinate.
DataArray seven_channels(const Mesh& m) {
  DataArray a{"seven", 7, {}, false};
  for (Index v = 0; v < m.vertex_count; ++v)
    for (int c = 0; c < 7; ++c) a.values.push_back(std::sin(1.3 * v + c) + 0.1 * c * m.positions[3 * v]);
  return a;
}

}  // namespace

TEST_CASE("every shipped surface scheme refines a 7-channel array exactly as it refines positions") {
  for (const SchemeListing& listing : list_schemes()) {
    if (listing.kind != "surface") continue;
    CAPTURE(listing.name);
    const auto scheme = load_scheme(listing.name);
    const Mesh mesh = mesh_for(*scheme);
    const SchemeRun run{scheme.get(), 2};
    RefineOptions o;
    const Hierarchy h = refine_topology(std::span(&run, 1), mesh.level(), o);
    LevelData level{mesh.positions, {seven_channels(mesh)}, {}};
    std::vector<double> channels = level.point_data[0].values;
    for (int l = 0; l < 2; ++l) {
      level = next_level_data(std::span(&run, 1), h, l, level, o);
      channels = step_values(std::span(&run, 1), h, l, channels, 7, o);
    }
    const std::vector<double> positions = interpolate(refine(*scheme, mesh.level(), [] {
      RefineOptions r;
      r.levels = 2;
      return r;
    }()), 2, mesh.positions, 3);
    REQUIRE(level.point_data[0].values.size() == channels.size());
    for (size_t i = 0; i < channels.size(); ++i) CHECK(level.point_data[0].values[i] == doctest::Approx(channels[i]).epsilon(1e-13));
    for (size_t i = 0; i < positions.size(); ++i) CHECK(level.positions[i] == doctest::Approx(positions[i]).epsilon(1e-13).scale(1));
  }
}

TEST_CASE("an affine function of the position stays that function; labels and face values are inherited") {
  const Mesh mesh = grid(4, 3);
  const Level base = mesh.level();
  DataArray temperature{"temperature", 1, {}, false};
  DataArray label{"label", 1, {}, true};
  DataArray material{"material", 1, {}, true};
  for (Index v = 0; v < mesh.vertex_count; ++v) {
    const double* p = &mesh.positions[3 * v];
    temperature.values.push_back(2 * p[0] - 3 * p[1] + 0.5);
    label.values.push_back(p[0] < 2 ? 7 : 9);  // a region id, split at x = 2
  }
  for (Index f = 0; f < base.face_count(); ++f) material.values.push_back(100 + f);
  const auto scheme = load_scheme("catmull-clark");
  const SchemeRun run{scheme.get(), 2};
  RefineOptions o;
  const Hierarchy h = refine_topology(std::span(&run, 1), base, o);
  LevelData level{mesh.positions, {temperature, label}, {material}};
  std::vector<Index> base_face(size_t(base.face_count()));
  for (Index f = 0; f < base.face_count(); ++f) base_face[f] = f;
  for (int l = 0; l < 2; ++l) {
    level = next_level_data(std::span(&run, 1), h, l, level, o);
    std::vector<Index> next(h.origins[l].parent_face.size());
    for (size_t f = 0; f < next.size(); ++f) next[f] = base_face[h.origins[l].parent_face[f]];
    base_face = std::move(next);
  }
  const Level& fine = h.levels.back();
  for (Index v = 0; v < fine.vertex_count; ++v) {
    const double* p = &level.positions[3 * v];
    CHECK(level.point_data[0].values[v] == doctest::Approx(2 * p[0] - 3 * p[1] + 0.5).epsilon(1e-13));
    // Labels: 7 left of x = 2, 9 right of it, the smaller (7) on points made between the two.
    const double id = level.point_data[1].values[v];
    CHECK((id == 7 || id == 9));
    if (p[0] < 2 - 1e-9) CHECK(id == 7);
    if (p[0] > 2 + 0.5 + 1e-9) CHECK(id == 9);
  }
  for (Index f = 0; f < fine.face_count(); ++f) CHECK(level.cell_data[0].values[f] == 100 + base_face[f]);
}

TEST_CASE("dual splits: vertex and edge faces take the value of their first corner's face") {
  const Mesh mesh = torus(5, 4);
  const Level base = mesh.level();
  DataArray material{"material", 1, {}, true};
  for (Index f = 0; f < base.face_count(); ++f) material.values.push_back(f);
  const auto scheme = load_scheme("doo-sabin");
  const SchemeRun run{scheme.get(), 1};
  RefineOptions o;
  const Hierarchy h = refine_topology(std::span(&run, 1), base, o);
  const LevelData next = next_level_data(std::span(&run, 1), h, 0, {mesh.positions, {}, {material}}, o);
  const Level& child = h.levels[1];
  const ChildOrigins& origins = h.origins[0];
  int dual_faces = 0;
  for (Index f = 0; f < child.face_count(); ++f) {
    const double got = next.cell_data[0].values[f];
    if (origins.parent_face[f] != kNone) {
      CHECK(got == origins.parent_face[f]);
      continue;
    }
    ++dual_faces;
    const Index first = child.face(f)[0];
    REQUIRE(origins.kind[first] == OriginKind::Corner);
    CHECK(got == origins.parent[first]);
  }
  CHECK(dual_faces == base.vertex_count + base.edge_count());  // V-faces and E-faces
}

TEST_CASE("normals are not carried, and non-finite data is refused with the array and the vertex named") {
  std::vector<std::string> dropped;
  const auto kept = carried_point_arrays({{"n", 3, {0, 0, 1}, false, ArrayRole::Normals}, {"t", 1, {1}, false}}, &dropped);
  REQUIRE(kept.size() == 1);
  CHECK(kept[0].name == "t");
  CHECK(dropped == std::vector<std::string>{"n"});
  LevelData bad{{0, 0, 0, 1, 0, 0}, {{"t", 1, {1, std::nan("")}, false}}, {}};
  CHECK_THROWS_WITH_AS(check_finite_arrays(bad, "m.vtp"), doctest::Contains("m.vtp: point array 't' holds nan at point 1"),
                       Error);
}
