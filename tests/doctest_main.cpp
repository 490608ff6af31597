// The test programs' main: the VTK formats registered as the `subdiv` tool registers them,
// so read_mesh and write_mesh handle .vtp/.vtk/.pvd in every test.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "framework/io/vtk/vtk_formats.h"

int main(int argc, char** argv) {
  subdiv::register_vtk_formats();
  return doctest::Context(argc, argv).run();
}
