// A fuzzed scheme refining a fuzzed small mesh for two levels, through the stencil tables
// and through step_values: JSON scheme text, a line "---", then an OBJ mesh (with crease and
// corner tags). Sizes are bounded so that every
// input runs in milliseconds: the point is the engine's handling of odd topology and odd
// rules, not memory exhaustion (which the memory guard handles before refining).
#include "fuzz_support.h"
#include "framework/io/mesh_level.h"
#include "framework/io/mesh_read.h"
#include "framework/engine/refiner.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"

namespace {

constexpr subdiv::Index kMaxFaces = 48, kMaxCorners = 192, kMaxVertices = 96;
constexpr int kLevels = 2;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Not a structured binding: clang 14 cannot capture those in the lambda below.
  const std::pair<std::string, std::string> texts = subdiv::fuzz::split_at(data, size, "\n---\n");
  const std::string& scheme_text = texts.first;
  const std::string& mesh_text = texts.second;
  static const std::string file = subdiv::fuzz::scratch_file(".obj");
  subdiv::fuzz::write_file(file, reinterpret_cast<const std::uint8_t*>(mesh_text.data()), mesh_text.size());
  subdiv::fuzz::expect_only_subdiv_errors([&] {
    const subdiv::MeshData mesh = subdiv::read_mesh(file);
    if (mesh.face_count() == 0 || mesh.face_count() > kMaxFaces || mesh.vertex_count() > kMaxVertices ||
        mesh.face_vertices.size() > std::size_t(kMaxCorners))
      return;
    const auto scheme = subdiv::load_scheme_text(scheme_text, "fuzz.json");
    subdiv::RefineOptions options;
    options.levels = kLevels;
    const subdiv::Hierarchy h = subdiv::refine(*scheme, subdiv::level_from_mesh(mesh, file), options);
    (void)subdiv::interpolate(h, kLevels, mesh.positions, 3);
    // The same levels without tables, as step_values computes them (flat and smooth kernels,
    // feature contexts classified on first use, the interpreter for the rest).
    std::vector<double> values = mesh.positions;
    for (int l = 0; l < kLevels; ++l) values = subdiv::step_values(*scheme, h, l, values, 3, options);
  });
  return 0;
}
