#include "framework/io/formats.h"
#include "io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

TEST_CASE("formats: extensions, case and help texts") {
  CHECK(lowercase_extension("a/B.OBJ") == ".obj");
  CHECK(lowercase_extension("noext") == "");
  CHECK(is_supported_input("x.Ply"));
  CHECK(is_supported_input("x.vtk"));
  CHECK_FALSE(is_supported_input("x.pvd"));
  CHECK(is_supported_output("x.pvd"));
  CHECK_FALSE(is_supported_output("x.om"));
  CHECK(is_vtk_output("out/levels.PVD"));
  CHECK(is_vtk_output("a.vtp"));
  CHECK_FALSE(is_vtk_output("a.vtk"));
  CHECK_FALSE(is_vtk_output("a.obj"));
  for (const char* ext : {".obj", ".off", ".ply", ".stl", ".om", ".vtp", ".vtk"})
    CHECK(contains(supported_input_formats(), ext));
  for (const char* ext : {".obj", ".off", ".ply", ".stl", ".vtp", ".pvd"})
    CHECK(contains(supported_output_formats(), ext));
}
