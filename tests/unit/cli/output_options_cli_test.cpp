// subdiv refine --arrays, --compression, --compression-level and the faces-only last level
// (tools/subdiv/output_options.h): exactly the chosen arrays, the same data whatever the
// compressor or thread count, the same output with and without the last level's edges, and
// bad values refused before any file is written.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "support/cli_checks.h"
#include "support/cli_runner.h"
#include "support/vtk_read.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

// A closed quad torus of nu x nv faces, as tools/bench/torus_obj.py writes it.
fs::path torus_obj(const fs::path& dir, int nu, int nv) {
  const fs::path file = dir / "torus.obj";
  std::ofstream out(file);
  out.precision(17);
  const double pi = std::acos(-1.0);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      out << "v " << (3 + std::cos(v)) * std::cos(u) << ' ' << (3 + std::cos(v)) * std::sin(u) << ' ' << std::sin(v)
          << '\n';
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      out << "f " << j * nu + i + 1 << ' ' << j * nu + (i + 1) % nu + 1 << ' ' << (j + 1) % nv * nu + (i + 1) % nu + 1
          << ' ' << (j + 1) % nv * nu + i + 1 << '\n';
  return file;
}

std::set<std::string> names(vtkFieldData& data) {
  std::set<std::string> out;
  for (int i = 0; i < data.GetNumberOfArrays(); ++i) out.insert(data.GetArrayName(i));
  return out;
}

std::vector<double> values(vtkDataArray& a) {
  std::vector<double> out(size_t(a.GetNumberOfValues()));
  const int c = a.GetNumberOfComponents();
  for (vtkIdType i = 0; i < a.GetNumberOfValues(); ++i) out[size_t(i)] = a.GetComponent(i / c, int(i % c));
  return out;
}

std::vector<vtkIdType> cells(vtkCellArray& c) {
  std::vector<vtkIdType> out;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (c.InitTraversal(); c.GetNextCell(n, ids);) {
    out.push_back(n);
    out.insert(out.end(), ids, ids + n);
  }
  return out;
}

// Same points, faces, lines, and every array of `b` in `a` with the same values.
void check_same_data(vtkPolyData& a, vtkPolyData& b) {
  REQUIRE(a.GetNumberOfPoints() == b.GetNumberOfPoints());
  CHECK(values(*a.GetPoints()->GetData()) == values(*b.GetPoints()->GetData()));
  CHECK(cells(*a.GetPolys()) == cells(*b.GetPolys()));
  CHECK(cells(*a.GetLines()) == cells(*b.GetLines()));
  for (vtkFieldData* data : {static_cast<vtkFieldData*>(b.GetPointData()), static_cast<vtkFieldData*>(b.GetCellData())})
    for (const std::string& name : names(*data)) {
      CAPTURE(name);
      vtkFieldData* other = data == b.GetPointData() ? static_cast<vtkFieldData*>(a.GetPointData()) : a.GetCellData();
      REQUIRE(other->GetArray(name.c_str()));
      CHECK(values(*other->GetArray(name.c_str())) == values(*data->GetArray(name.c_str())));
    }
}

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const std::set<std::string> kPointArrays = {"origin", "valence", "level", "vertex_class", "corner_sharpness"};
const std::set<std::string> kCellArrays = {"parent_face", "base_face", "sharpness", "cell_kind"};

}  // namespace

TEST_CASE("--arrays writes exactly the chosen arrays to .vtp and to every level of .pvd") {
  const auto dir = fresh_dir("cli-arrays");
  const std::string cube = source_path("examples/meshes/cube-creased.obj");
  struct Case {
    std::string option;
    std::set<std::string> point, cell;
  };
  // The default as README and `subdiv refine --help` document it.
  const Case cases[] = {{"", {"corner_sharpness"}, {"base_face", "sharpness", "cell_kind"}},
                        {"--arrays all", kPointArrays, kCellArrays},
                        {"--arrays none", {}, {}},
                        {"--arrays valence,base_face", {"valence"}, {"base_face"}},
                        {"--arrays default,origin",
                         {"origin", "corner_sharpness"},
                         {"base_face", "sharpness", "cell_kind"}}};
  for (const Case& c : cases) {
    CAPTURE(c.option);
    const auto vtp = dir / "cube.vtp", pvd = dir / "cube.pvd";
    for (const auto& out : {vtp, pvd}) {
      const CliResult r = run_subdiv("refine " + cube + " -l 2 " + c.option + " -o " + out.string());
      REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    }
    for (const auto& file : {vtp, dir / "cube_levels" / "level_0.vtp", dir / "cube_levels" / "level_2.vtp"}) {
      const auto poly = read_vtp(file);
      CHECK(names(*poly->GetPointData()) == c.point);
      CHECK(names(*poly->GetCellData()) == c.cell);
      CHECK(poly->GetNumberOfLines() > 0);  // the creases are written whatever the arrays
    }
  }
}

TEST_CASE("--arrays, --compression and --compression-level: bad values are refused, no file written") {
  const auto dir = fresh_dir("cli-arrays-bad");
  const std::string cube = "refine " + source_path("examples/meshes/cube.obj");
  for (const auto& out : {dir / "out.vtp", dir / "out.pvd", dir / "out.obj"}) {
    check_refused(cube + " --arrays valence,nosuch", out, "--arrays 'valence,nosuch': unknown array 'nosuch'");
    check_refused(cube + " --arrays valence,nosuch", out, "origin, valence, level, vertex_class");
    check_refused(cube + " --arrays none,valence", out, "'none' stands alone");
    check_refused(cube + " --arrays valence,", out, "--arrays 'valence,': an empty name");
    check_refused(cube + " --compression lz5", out,
                  "--compression 'lz5' is not a compressor; use one of zlib, lz4, lzma, none");
    check_refused(cube + " --compression-level 10", out, "--compression-level");
    check_refused(cube + " --vtp-encoding hex", out, "--vtp-encoding 'hex' is not an encoding; use base64 or raw");
    CHECK_FALSE(fs::exists(dir / "out_levels"));
  }
}

TEST_CASE("every compressor and level writes the same data, named in the file; VTK's reader reads them all") {
  const auto dir = fresh_dir("cli-compression");
  const auto mesh = torus_obj(dir, 40, 30);  // level 2: 19200 faces, several blocks per array at level 1
  const auto reference = dir / "zlib.vtp";
  REQUIRE(run_subdiv("refine " + mesh.string() + " -l 2 --arrays all --compression-level 9 -o " + reference.string())
              .exit_code == 0);
  const auto expected = read_vtp(reference);
  const std::pair<std::string, std::string> cases[] = {{"zlib", "vtkZLibDataCompressor"},
                                                       {"lz4", "vtkLZ4DataCompressor"},
                                                       {"lzma", "vtkLZMADataCompressor"},
                                                       {"none", ""}};
  for (const auto& named : cases) {
    // (No structured binding: clang 14 cannot capture one in doctest's CAPTURE.)
    const std::string& name = named.first;
    const std::string& compressor = named.second;
    for (const char* level : {"1", "5"}) {
      CAPTURE(name);
      CAPTURE(level);
      const auto out = dir / (name + level + ".vtp");
      const CliResult r = run_subdiv("refine " + mesh.string() + " -l 2 --arrays all --compression " + name +
                                     " --compression-level " + level + " -o " + out.string());
      REQUIRE_MESSAGE(r.exit_code == 0, r.output);
      const std::string text = file_text(out);
      if (compressor.empty()) CHECK(text.find("compressor=") == std::string::npos);
      else CHECK(text.find("compressor=\"" + compressor + "\"") != std::string::npos);
      check_same_data(*read_vtp(out), *expected);
    }
  }
}

TEST_CASE("--vtp-encoding raw: raw appended data, the same data as base64, in .vtp and .pvd") {
  const auto dir = fresh_dir("cli-vtp-encoding");
  const auto mesh = torus_obj(dir, 40, 30);
  const auto reference = dir / "base64.vtp";
  REQUIRE(run_subdiv("refine " + mesh.string() + " -l 2 --arrays all -o " + reference.string()).exit_code == 0);
  CHECK(file_text(reference).find("<AppendedData") == std::string::npos);
  const auto expected = read_vtp(reference);
  for (const char* compression : {"lz4", "zlib", "none"}) {
    CAPTURE(compression);
    const auto out = dir / (std::string("raw-") + compression + ".vtp");
    const CliResult r = run_subdiv("refine " + mesh.string() + " -l 2 --arrays all --vtp-encoding raw --compression " +
                                   compression + " -o " + out.string());
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    CHECK(file_text(out).find("<AppendedData encoding=\"raw\">") != std::string::npos);
    check_same_data(*read_vtp(out), *expected);
  }
  const CliResult r = run_subdiv("refine " + mesh.string() + " -l 2 --vtp-encoding raw -o " + (dir / "all.pvd").string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(file_text(dir / "all_levels" / "level_2.vtp").find("<AppendedData encoding=\"raw\">") != std::string::npos);
}

TEST_CASE("the file is the same byte for byte for any thread count") {
  const auto dir = fresh_dir("cli-compression-threads");
  const auto mesh = torus_obj(dir, 120, 100);  // level 2: 192000 faces, points in 5 blocks of 1 MB
  for (const char* compression : {"zlib", "lz4", "lzma"}) {
    CAPTURE(compression);
    std::string first;
    for (const char* threads : {"1", "2", "4"}) {
      const auto out = dir / (std::string(compression) + threads + ".vtp");
      const CliResult r = run_subdiv("refine " + mesh.string() + " -l 2 --compression " + compression + " -j " +
                                     threads + " -o " + out.string());
      REQUIRE_MESSAGE(r.exit_code == 0, r.output);
      if (first.empty()) first = file_text(out);
      else CHECK(file_text(out) == first);
    }
  }
}

TEST_CASE("a faces-only last level writes what full topology writes") {
  const auto dir = fresh_dir("cli-faces-only");
  const auto torus = torus_obj(dir, 12, 9);
  struct Case {
    std::string mesh, scheme;
  };
  const Case cases[] = {{torus.string(), "catmull-clark"}, {source_path("examples/meshes/octahedron.obj"), "loop"},
                        {source_path("examples/meshes/pyramid.obj"), "catmull-clark"}};
  for (const Case& c : cases) {
    for (const char* ext : {".vtp", ".pvd"}) {
      CAPTURE(c.mesh);
      CAPTURE(ext);
      // Default arrays: faces only. Asking for valence as well needs the last level's rings.
      const auto fast = dir / (std::string("fast") + ext), full = dir / (std::string("full") + ext);
      const std::string refine = "refine " + c.mesh + " -s " + c.scheme + " -l 2 --timings ";
      const CliResult a = run_subdiv(refine + "-o " + fast.string());
      const CliResult b = run_subdiv(refine + "--arrays default,valence -o " + full.string());
      REQUIRE_MESSAGE(a.exit_code == 0, a.output);
      REQUIRE_MESSAGE(b.exit_code == 0, b.output);
      CHECK(a.output.find("(last level: faces only)") != std::string::npos);
      CHECK(b.output.find("(last level: faces only)") == std::string::npos);
      const auto last = [&](const fs::path& f) {
        return std::string(ext) == ".pvd" ? f.parent_path() / (f.stem().string() + "_levels") / "level_2.vtp" : f;
      };
      check_same_data(*read_vtp(last(full)), *read_vtp(last(fast)));
    }
    // Mesh formats hold none of the arrays: always faces only (when the mesh has no features).
    const CliResult obj = run_subdiv("refine " + c.mesh + " -s " + c.scheme + " -l 2 --timings --arrays all -o " +
                                     (dir / "fast.obj").string());
    CHECK(obj.output.find("(last level: faces only)") != std::string::npos);
  }
}

TEST_CASE("features keep the last level's full topology: creases and corners are written as before") {
  const auto dir = fresh_dir("cli-faces-only-features");
  const auto out = dir / "cube.vtp";
  const CliResult r = run_subdiv("refine " + source_path("examples/meshes/cube-creased.obj") + " -l 2 --timings -o " +
                                 out.string());
  REQUIRE_MESSAGE(r.exit_code == 0, r.output);
  CHECK(r.output.find("(last level: faces only)") == std::string::npos);
  CHECK(read_vtp(out)->GetNumberOfLines() > 0);
}
