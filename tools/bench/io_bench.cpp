// subdiv-bench-io: SubdivKit's mesh writers and readers against VTK's and OpenMesh's on the
// same data (issue 32 item 3; docs/benchmarks.md, "Writing and reading").
//
// Writing: one generated quad torus (by default 16M faces, the size of Catmull-Clark level 2
// of the 1M torus) as the same vtkPolyData (polydata_from_level: the arrays write_vtp writes)
// through write_vtp's defaults (inline base64, LZ4, 1 MB blocks, 64-bit headers) and through
// vtkXMLPolyDataWriter set the same way. Each side writes two files in a row after a sync: the
// first with a clean page cache, the second right after it, while the first one's pages are
// still dirty (what a user writing several levels or pieces meets). Rounds alternate the
// sides. Reading: the files SubdivKit writes (.vtp, .obj, .ply), read by read_mesh, by VTK's
// readers and by OpenMesh's, each file warm in the page cache, best of the rounds.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include "bench_mesh.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "framework/io/output_level.h"
#include "framework/io/vtk/polydata_conversion.h"
#include "framework/io/vtk/vtk_formats.h"
#include "framework/io/vtk/vtk_output.h"
#include "framework/io/vtk/vtk_read.h"

namespace {

namespace fs = std::filesystem;
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

double user_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec) + double(u.ru_utime.tv_usec) * 1e-6;
}

double system_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_stime.tv_sec) + double(u.ru_stime.tv_usec) * 1e-6;
}

// Wall time of `work`; its process user and system time (all threads) into *user and
// *system when given.
double seconds_of(const std::function<void()>& work, double* user = nullptr, double* system = nullptr) {
  const double u0 = user_seconds(), s0 = system_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  work();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (user) *user = user_seconds() - u0;
  if (system) *system = system_seconds() - s0;
  return wall;
}

// The same settings write_vtp uses (framework/io/vtk/vtk_polydata.cpp), with VTK's own LZ4.
void vtk_write(vtkPolyData* poly, const fs::path& file) {
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(poly);
  writer->SetFileName(file.c_str());
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToLZ4();
  writer->SetBlockSize(1 << 20);
  writer->SetHeaderTypeToUInt64();
  if (writer->Write() != 1) throw std::runtime_error("vtkXMLPolyDataWriter failed on " + file.string());
}

template <class Reader>
vtkIdType vtk_read(const fs::path& file) {
  vtkNew<Reader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput()->GetNumberOfCells();
}

size_t openmesh_read(const fs::path& file) {
  OmMesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, file.string())) throw std::runtime_error("OpenMesh cannot read " + file.string());
  return mesh.n_faces();
}

// The best round's wall time and that round's user and system time.
struct Best {
  double s = std::numeric_limits<double>::infinity(), user = 0, system = 0;
  void take(double t, double u = 0, double sys = 0) {
    if (t < s) s = t, user = u, system = sys;
  }
};

double gb(const fs::path& file) { return double(fs::file_size(file)) / 1e9; }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"subdiv-bench-io: SubdivKit's writers and readers against VTK's and OpenMesh's"};
  long long faces = 16000000;
  int rounds = 2;
  std::string dir = "/tmp";
  bool reads = true, writes = true;
  app.add_option("--faces", faces, "Faces of the generated quad torus")->capture_default_str();
  app.add_option("--rounds", rounds, "Rounds, alternating the sides; best of each")->capture_default_str();
  app.add_option("--dir", dir, "Where the files go (removed at the end)")->capture_default_str();
  app.add_option("--reads", reads, "Also time the readers (VTK's OBJ reader takes minutes at 16M faces)")
      ->capture_default_str();
  app.add_option("--writes", writes, "Also time the writers (false: write each file once, untimed)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  subdiv::register_vtk_formats();

  const subdiv_bench::Mesh m = subdiv_bench::make_mesh("torus", faces);
  subdiv::MeshData mesh;
  mesh.positions = m.xyz;
  mesh.face_offsets.assign(m.face_offsets.begin(), m.face_offsets.end());
  mesh.face_vertices.assign(m.face_vertices.begin(), m.face_vertices.end());
  const subdiv::OutputLevel level{&mesh, 0, {}, {}};
  const auto poly = subdiv::polydata_from_level(level, "bench");
  const fs::path base = fs::path(dir) / ("subdiv-bench-io-" + std::to_string(getpid()));
  const auto file = [&](const std::string& name) { return fs::path(base.string() + "-" + name); };
  double loadavg[3] = {};
  getloadavg(loadavg, 3);
  std::printf("# subdiv-bench-io: torus faces=%d vertices=%d rounds=%d loadavg=%.2f %.2f %.2f\n", m.face_count(),
              m.vertex_count, rounds, loadavg[0], loadavg[1], loadavg[2]);

  // Writing: [side][first, second]
  Best ours[2], vtk[2];
  if (!writes) subdiv::write_vtp(file("ours-a.vtp"), level);
  for (int r = 0; writes && r < rounds; ++r) {
    double user = 0, system = 0, wall = 0;
    sync();
    wall = seconds_of([&] { subdiv::write_vtp(file("ours-a.vtp"), level); }, &user, &system);
    ours[0].take(wall, user, system);
    wall = seconds_of([&] { subdiv::write_vtp(file("ours-b.vtp"), level); }, &user, &system);
    ours[1].take(wall, user, system);
    sync();
    wall = seconds_of([&] { vtk_write(poly, file("vtk-a.vtp")); }, &user, &system);
    vtk[0].take(wall, user, system);
    wall = seconds_of([&] { vtk_write(poly, file("vtk-b.vtp")); }, &user, &system);
    vtk[1].take(wall, user, system);
  }
  const double ours_gb = gb(file("ours-a.vtp")), vtk_gb = writes ? gb(file("vtk-a.vtp")) : 0;
  for (int k = 0; writes && k < 2; ++k)
    std::printf("write %s vtp_gb=%.3f subdivkit_s=%.3f subdivkit_user_s=%.3f subdivkit_sys_s=%.3f "
                "subdivkit_gb_per_s=%.2f vtk_gb=%.3f vtk_s=%.3f vtk_user_s=%.3f vtk_sys_s=%.3f ratio=%.2f "
                "user_ratio=%.2f\n",
                k == 0 ? "clean" : "dirty", ours_gb, ours[k].s, ours[k].user, ours[k].system, ours_gb / ours[k].s,
                vtk_gb, vtk[k].s, vtk[k].user, vtk[k].system, ours[k].s / vtk[k].s, ours[k].user / vtk[k].user);
  if (writes) fs::remove(file("ours-b.vtp")), fs::remove(file("vtk-a.vtp")), fs::remove(file("vtk-b.vtp"));
  if (!reads) {
    fs::remove(file("ours-a.vtp"));
    return 0;
  }

  // Reading the files SubdivKit writes, warm: .vtp with the defaults (inline base64, LZ4) and
  // with raw appended data (--vtp-encoding raw, LZ4), .obj, binary .ply.
  subdiv::write_mesh(file("m.obj"), mesh);
  subdiv::write_mesh(file("m.ply"), mesh);
  subdiv::VtkWriteOptions raw;
  raw.encoding = subdiv::VtkEncoding::Raw;
  subdiv::write_vtp(file("raw.vtp"), level, raw);
  constexpr int kFiles = 4;
  // For .vtp also read_mesh's former path (the check, VTK's reader, the conversion: what the
  // fast path replaced, vtp_fast_read.h), to give before and after in one run.
  Best read_ours[kFiles], read_vtk[kFiles], read_om[kFiles], read_before[kFiles];
  const char* names[kFiles] = {"vtp", "vtp-raw", "obj", "ply"};
  const fs::path files[kFiles] = {file("ours-a.vtp"), file("raw.vtp"), file("m.obj"), file("m.ply")};
  size_t checked = 0;
  for (int r = 0; r < rounds; ++r)
    for (int k = 0; k < kFiles; ++k) {
      double user = 0, wall = 0;
      wall = seconds_of([&] { checked += subdiv::read_mesh(files[k]).face_offsets.size() - 1; }, &user);
      read_ours[k].take(wall, user);
      if (k <= 1) wall = seconds_of([&] { checked += size_t(vtk_read<vtkXMLPolyDataReader>(files[k])); }, &user);
      if (k == 2) wall = seconds_of([&] { checked += size_t(vtk_read<vtkOBJReader>(files[k])); }, &user);
      if (k == 3) wall = seconds_of([&] { checked += size_t(vtk_read<vtkPLYReader>(files[k])); }, &user);
      read_vtk[k].take(wall, user);
      if (k >= 2) {
        wall = seconds_of([&] { checked += openmesh_read(files[k]); }, &user);
        read_om[k].take(wall, user);
      } else {
        wall = seconds_of([&] {
          checked += subdiv::io_detail::read_vtk_polydata_with_vtk(files[k]).face_offsets.size() - 1;
        }, &user);
        read_before[k].take(wall, user);
      }
    }
  getloadavg(loadavg, 3);
  for (int k = 0; k < kFiles; ++k)
    std::printf("read %s gb=%.3f subdivkit_s=%.3f subdivkit_user_s=%.3f vtk_s=%.3f vtk_user_s=%.3f vtk_ratio=%.2f "
                "openmesh_s=%.3f openmesh_user_s=%.3f openmesh_ratio=%.2f before_s=%.3f before_user_s=%.3f "
                "before_vtk_ratio=%.2f\n",
                names[k], gb(files[k]), read_ours[k].s, read_ours[k].user, read_vtk[k].s, read_vtk[k].user,
                read_ours[k].s / read_vtk[k].s, k >= 2 ? read_om[k].s : 0.0, k >= 2 ? read_om[k].user : 0.0,
                k >= 2 ? read_ours[k].s / read_om[k].s : 0.0, k < 2 ? read_before[k].s : 0.0,
                k < 2 ? read_before[k].user : 0.0, k < 2 ? read_before[k].s / read_vtk[k].s : 0.0);
  std::printf("# loadavg at the end=%.2f %.2f %.2f\n", loadavg[0], loadavg[1], loadavg[2]);
  const bool all_faces = checked == size_t(m.face_count()) * size_t(rounds) * 3 * kFiles;
  std::printf("faces_read %s\n", all_faces ? "all" : "MISMATCH");
  for (const fs::path& f : files) fs::remove(f);
  return all_faces ? 0 : 1;
}
