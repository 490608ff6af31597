// The writers, read back (issue 33): a small mesh of quads with fuzzed coordinates and
// point and cell arrays of fuzzed names, sizes, roles and values is written in every output
// format and read again with SubdivKit's readers. A write may refuse (subdiv::Error, and then
// no file may be left); a file that was written must read back, with the same positions
// (bit for bit, STL as floats), the same faces, and for .vtp the same arrays. Anything else
// (a writer producing what no reader takes: unescaped names, inf ranges, forged PLY header
// lines) is a finding.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <set>

#include "fuzz_support.h"
#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"

namespace {

namespace fs = std::filesystem;
using subdiv::DataArray;
using subdiv::Index;
using subdiv::MeshData;

[[noreturn]] void finding(const char* format, const std::string& what) {
  std::fprintf(stderr, "fuzz_write_read: %s: %s\n", format, what.c_str());
  std::abort();
}

DataArray fuzzed_array(FuzzedDataProvider& in, std::size_t tuples) {
  DataArray a;
  a.name = in.ConsumeRandomLengthString(24);
  a.components = in.ConsumeIntegralInRange<int>(1, 4);
  a.integer = in.ConsumeBool();
  a.role = static_cast<subdiv::ArrayRole>(in.ConsumeIntegralInRange<int>(0, 3));
  for (std::size_t i = 0; i < tuples * std::size_t(a.components); ++i)
    a.values.push_back(a.integer ? double(in.ConsumeIntegralInRange<int>(-1000, 1000)) : in.ConsumeFloatingPoint<double>());
  return a;
}

MeshData fuzzed_mesh(FuzzedDataProvider& in) {
  MeshData m;
  const int nx = in.ConsumeIntegralInRange<int>(1, 4), ny = in.ConsumeIntegralInRange<int>(1, 4);
  for (int i = 0; i < 3 * (nx + 1) * (ny + 1); ++i) m.positions.push_back(in.ConsumeFloatingPoint<double>());
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Index v = Index(j * (nx + 1) + i);
      m.face_vertices.insert(m.face_vertices.end(), {v, Index(v + 1), Index(v + nx + 2), Index(v + nx + 1)});
      m.face_offsets.push_back(Index(m.face_vertices.size()));
    }
  const int points = in.ConsumeIntegralInRange<int>(0, 2), cells = in.ConsumeIntegralInRange<int>(0, 2);
  for (int k = 0; k < points; ++k) m.point_data.push_back(fuzzed_array(in, std::size_t(m.vertex_count())));
  for (int k = 0; k < cells; ++k) m.cell_data.push_back(fuzzed_array(in, std::size_t(m.face_count())));
  return m;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Names the .vtp reader leaves out (SubdivKit's own arrays, recomputed on refinement).
bool subdivkit_name(const std::string& name) {
  static const std::set<std::string> names = {"corner_sharpness", "origin", "valence", "level", "vertex_class",
                                              "limit_exact", "normal_exact", "cell_kind", "sharpness",
                                              "parent_face", "base_face"};
  return names.count(name) > 0;
}

void check_vtp_arrays(const std::vector<DataArray>& written, const std::vector<DataArray>& read) {
  std::size_t r = 0;
  for (const DataArray& a : written) {
    if (subdivkit_name(a.name)) continue;
    if (r >= read.size()) finding(".vtp", "an array is missing: '" + a.name + "'");
    const DataArray& b = read[r++];
    if (b.name != a.name) finding(".vtp", "array '" + a.name + "' came back as '" + b.name + "'");
    if (b.components != a.components || !same_bits(a.values, b.values))
      finding(".vtp", "array '" + a.name + "' came back with other values");
  }
}

void round_trip(const fs::path& dir, const char* format, const MeshData& mesh) {
  const fs::path file = dir / (std::string("mesh") + format);
  bool written = true;
  try {
    subdiv::write_mesh(file, mesh);
  } catch (const subdiv::Error&) {
    written = false;
  }
  if (!written) {
    if (!fs::is_empty(dir)) finding(format, "a refused write left a file behind");
    return;
  }
  MeshData back;
  try {
    back = subdiv::read_mesh(file);
  } catch (const subdiv::Error& e) {
    finding(format, std::string("the written file does not read back: ") + e.what());
  }
  if (std::strcmp(format, ".stl") != 0) {
    if (!same_bits(mesh.positions, back.positions)) finding(format, "positions changed");
    if (back.face_offsets != mesh.face_offsets || back.face_vertices != mesh.face_vertices)
      finding(format, "faces changed");
  } else if (back.face_count() != 2 * mesh.face_count()) {
    finding(format, "STL has another number of triangles");
  }
  if (std::strcmp(format, ".vtp") == 0) {
    check_vtp_arrays(mesh.point_data, back.point_data);
    check_vtp_arrays(mesh.cell_data, back.cell_data);
  }
  fs::remove(file);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fs::path dir = [] {
    const fs::path d = fs::path(subdiv::fuzz::scratch_file(".dir"));
    fs::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(fs::path(subdiv::fuzz::scratch_file(".dir")), ec);
    });
    return d;
  }();
  FuzzedDataProvider in(data, size);
  const MeshData mesh = fuzzed_mesh(in);
  for (const char* format : {".obj", ".off", ".ply", ".stl", ".vtp"})
    subdiv::fuzz::expect_only_subdiv_errors([&] { round_trip(dir, format, mesh); });
  return 0;
}
