// One reader per build: FUZZ_EXTENSION (".obj", ".off", ".ply", ".stl", ".vtp", ".vtk",
// ".om") picks the format read_mesh dispatches to. The input is written to a scratch
// file because the readers take paths (VTK and OpenMesh read files themselves).
#include "fuzz_support.h"
#include "framework/io/mesh_read.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string file = subdiv::fuzz::scratch_file(FUZZ_EXTENSION);
  subdiv::fuzz::write_file(file, data, size);
  subdiv::fuzz::expect_only_subdiv_errors([&] { (void)subdiv::read_mesh(file); });
  return 0;
}
