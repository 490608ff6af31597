// SubdivKit::vtkio against the installed package: with the VTK formats registered,
// write_mesh writes a .vtp and read_mesh reads it back with the same points and faces.
#include <cstdio>

#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/io/vtk/vtk_formats.h"
#include "framework/util/error.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: uses_vtkio MESH OUT.vtp\n");
    return 2;
  }
  try {
    subdiv::register_vtk_formats();
    const subdiv::MeshData mesh = subdiv::read_mesh(argv[1]);
    subdiv::write_mesh(argv[2], mesh);
    const subdiv::MeshData back = subdiv::read_mesh(argv[2]);
    std::printf("uses_vtkio: %zu points, %zu faces through %s\n", back.positions.size() / 3,
                size_t(back.face_count()), argv[2]);
    return back.positions == mesh.positions && back.face_vertices == mesh.face_vertices ? 0 : 1;
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "uses_vtkio: %s\n", e.what());
    return 1;
  }
}
