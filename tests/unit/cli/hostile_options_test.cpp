// `subdiv refine` options and inputs a hostile or unlucky user gives: NaN angles,
// absurd start levels, sequences that do not add up to --levels, input paths that are
// FIFOs or devices, VTK files that make VTK print, and process memory limits. Each run
// must exit non-zero with a message naming the problem, and leave no output file.
#include <doctest/doctest.h>

#include <filesystem>
#include <initializer_list>
#include <fstream>
#include <regex>
#include <sys/stat.h>

#include "support/cli_checks.h"
#include "support/cli_runner.h"
#include "support/sanitizers.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

const std::string kCube = source_path("examples/meshes/cube.obj");

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// `timeout` so that a regression to a hang fails the test instead of stalling the suite.
CliResult run_bounded(const std::string& args) { return run_subdiv_with_prefix("timeout 60 ", args); }

}  // namespace

TEST_CASE("--feature-angle nan and --start-level 2147483647 are refused") {
  const auto dir = fresh_dir("hostile-options");
  check_refused("refine " + kCube + " --feature-angle nan", dir / "a.obj", "--feature-angle nan is not an angle");
  check_refused("refine " + kCube + " --start-level 2147483647", dir / "b.obj", "--start-level");
  check_refused("refine " + kCube + " --start-level 101", dir / "c.obj", "--start-level");
  CHECK(run_subdiv("refine " + kCube + " --start-level 2 -q -o " + (dir / "ok.obj").string()).exit_code == 0);
}

TEST_CASE("a scheme sequence that does not add up to an explicit --levels is refused") {
  const auto dir = fresh_dir("hostile-sequence");
  check_refused("refine " + kCube + " -s catmull-clark:1,catmull-clark:2 -l 2", dir / "a.obj",
                "--scheme 'catmull-clark:1,catmull-clark:2' runs 3 level(s), but --levels asks for 2");
  check_refused("refine " + kCube + " -s catmull-clark:1 -l 3", dir / "b.obj", "runs 1 level(s), but --levels asks for 3");
  check_refused("refine " + kCube + " -s catmull-clark:99999999999,catmull-clark:1", dir / "c.obj",
                "should be NAME:LEVELS with LEVELS a whole number from 0 to 30");
  check_refused("refine " + kCube + " -s catmull-clark:2147483647,catmull-clark:2147483647", dir / "d.obj",
                "a whole number from 0 to 30");
  // Without -l the sequence sets the total, as docs/scheme-format.md shows; with a matching -l too.
  CHECK(run_subdiv("refine " + kCube + " -s catmull-clark:1,catmull-clark:1 -q -o " + (dir / "ok.obj").string()).exit_code == 0);
  CHECK(run_subdiv("refine " + kCube + " -s catmull-clark:1,catmull-clark -l 3 -q -o " + (dir / "ok.obj").string())
            .exit_code == 0);
}

TEST_CASE("input paths that are FIFOs or symlinks to devices are refused at once") {
  const auto dir = fresh_dir("hostile-paths");
  const fs::path fifo = dir / "pipe.obj";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const CliResult r = run_bounded("refine " + fifo.string() + " -o " + (dir / "a.obj").string());
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "cannot open '" + fifo.string() + "': it is a FIFO (named pipe)"));
  CHECK_FALSE(fs::exists(dir / "a.obj"));

  fs::create_symlink("/dev/zero", dir / "zero.obj");
  const CliResult zero = run_bounded("refine " + (dir / "zero.obj").string() + " -o " + (dir / "b.obj").string());
  CHECK(zero.exit_code == 1);
  CHECK(contains(zero.output, "it is a character device"));
  fs::create_symlink("/dev/zero", dir / "zero.json");
  const CliResult scheme = run_bounded("refine " + kCube + " -s " + (dir / "zero.json").string() + " -o " +
                                       (dir / "c.obj").string());
  CHECK(scheme.exit_code == 1);
  CHECK(contains(scheme.output, "regular scheme file"));
  const CliResult features = run_bounded("refine " + kCube + " --features " + fifo.string() + " -o " +
                                         (dir / "d.obj").string());
  CHECK(features.exit_code == 1);
  CHECK(contains(features.output, "regular feature file"));
}

TEST_CASE("refine refuses an output no file can be written to before any work") {
  // A missing folder was found only when the finished level was written. Level 13 of the
  // cube would not fit in memory: a refusal about the place, not about memory, shows that
  // the place was checked first.
  const auto dir = fresh_dir("hostile-output-place");
  fs::create_directory(dir / "folder.obj");
  for (const auto& bad :
       {std::pair<fs::path, const char*>{dir / "missing" / "a.obj", "does not exist; create it first"},
        {dir / "folder.obj", "it is a directory"},
        {dir / "missing" / "a.pvd", "does not exist; create it first"}}) {
    const fs::path& out = bad.first;
    const char* message = bad.second;
    CAPTURE(out);
    const CliResult r = run_bounded("refine " + kCube + " -l 13 -o " + out.string());
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.output, message), r.output);
    CHECK_MESSAGE(!contains(r.output, "GiB"), r.output);
  }
  CHECK_FALSE(fs::exists(dir / "missing"));
}

TEST_CASE("VTK's own output never reaches the terminal; the message is ours and names the file") {
  const auto dir = fresh_dir("hostile-vtk");
  std::ofstream(dir / "bad.vtp") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\">\n"
                                    "<PolyData><Piece NumberOfPoints=\"3\" NumberOfPolys=\"2\">\n<Points>"
                                    "<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0"
                                    "</DataArray></Points>\n<Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2"
                                    "</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">5 3</DataArray></Polys>\n"
                                    "</Piece></PolyData></VTKFile>\n";  // offsets that decrease: VTK fails
  const CliResult r = run_bounded("refine " + (dir / "bad.vtp").string() + " -o " + (dir / "a.obj").string());
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "subdiv: error: cannot read '" + (dir / "bad.vtp").string() + "'"));
  CHECK_FALSE(contains(r.output, "\x1b["));       // ANSI colours
  CHECK_FALSE(contains(r.output, "ERROR: In "));  // VTK's source-file prefix
  CHECK_FALSE(contains(r.output, "vtkInformation"));
  CHECK_FALSE(contains(r.output, "internal error"));
  CHECK_FALSE(fs::exists(dir / "a.obj"));
}

// `command` (its output file `out` appended) under a 0.4 GB address-space limit: refused
// with exit 1 and `messages`, naming the limit, never an internal error, no file left.
void check_refused_within_400_mb(const std::string& command, const fs::path& out,
                                 std::initializer_list<const char*> messages) {
  const CliResult r = run_subdiv_with_prefix("ulimit -v 400000; ", command + out.string());
  INFO(command, r.output);
  CHECK(r.exit_code == 1);
  for (const char* m : messages) CHECK(contains(r.output, m));
  CHECK(contains(r.output, "RLIMIT_AS (ulimit -v)"));
  CHECK_FALSE(contains(r.output, "internal error"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("a process memory limit (ulimit -v) is honoured by the memory guard") {
#if SUBDIV_TEST_ASAN
  MESSAGE("skipped: AddressSanitizer reserves terabytes of address space, so ulimit -v cannot apply");
#else
  // 9 levels of Catmull-Clark on the cube: 1.6 million faces, about 0.5 GB.
  check_refused_within_400_mb("refine " + kCube + " -l 9 -o ", fresh_dir("hostile-memory") / "big.obj",
                              {"9 levels would make about"});
#endif
}

TEST_CASE("adaptive refinement that would not fit (a tolerance near 0 asks for the uniform level) is refused before the level") {
#if SUBDIV_TEST_ASAN
  MESSAGE("skipped: AddressSanitizer reserves terabytes of address space, so ulimit -v cannot apply");
#else
  // Every face split to level 12: 25 million faces, refused at the first level that would not
  // fit instead of failing (or being killed) inside it.
  const auto dir = fresh_dir("hostile-adaptive-memory");
  for (const char* command : {"refine ", "evaluate "})
    check_refused_within_400_mb(command + kCube + " --adaptive 12 --tolerance 1e-300 -o ", dir / "big.vtp",
                                {"adaptive refinement: level ", "ask for fewer levels or a larger tolerance"});
#endif
}

TEST_CASE("evaluate --level-distance that would not fit is refused before its first level") {
#if SUBDIV_TEST_ASAN
  MESSAGE("skipped: AddressSanitizer reserves terabytes of address space, so ulimit -v cannot apply");
#else
  // The uniform level 12 of the cube: its last stage (25 million faces split) is checked
  // before any stage is made, so the message names level 12, not the first level past the
  // limit (9 here, after 8 levels of work; 40 s at the machine's own limit).
  check_refused_within_400_mb("evaluate " + kCube + " --level-distance 12 -o ",
                              fresh_dir("hostile-level-distance-memory") / "big.vtp",
                              {"adaptive refinement: level 12 would split 25165824 faces", "ask for a lower level"});
#endif
}

TEST_CASE("a sampled limit surface that would not fit is refused before any sample") {
#if SUBDIV_TEST_ASAN
  MESSAGE("skipped: AddressSanitizer reserves terabytes of address space, so ulimit -v cannot apply");
#else
  // 1024 x 1024 samples per face of the cube: 6.3 million points, about 1.5 GB.
  check_refused_within_400_mb("evaluate " + kCube + " --samples 1024 -o ",
                              fresh_dir("hostile-samples-memory") / "big.vtp",
                              {"--samples 1024: 6.3e+06 sample points would need about", "ask for fewer samples per edge"});
#endif
}

TEST_CASE("--samples counts what sampling really holds: 420 on the cube under 440 MB is refused before any sample") {
#if SUBDIV_TEST_ASAN
  MESSAGE("skipped: AddressSanitizer reserves terabytes of address space, so ulimit -v cannot apply");
#else
  // 1.06 million points need about 380 B each at the peak (the least ulimit -v that lets it
  // finish); 0.24 kB were counted, so the check passed and the run ran out of memory half-way,
  // told to "ask for fewer levels", which --samples has none of.
  const auto out = fresh_dir("hostile-samples-honest-memory") / "big.vtp";
  const CliResult r = run_subdiv_with_prefix("ulimit -v 440000; ", "evaluate " + kCube + " --samples 420 -o " + out.string());
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "--samples 420: 1.06e+06 sample points would need about"));
  CHECK(contains(r.output, "ask for fewer samples per edge"));
  CHECK_FALSE(contains(r.output, "levels"));
  CHECK_FALSE(fs::exists(out));
#endif
}

TEST_CASE("running out of memory part-way through --at names the fix for points, not levels") {
#if SUBDIV_TEST_ASAN
  MESSAGE("skipped: AddressSanitizer reserves terabytes of address space, so ulimit -v cannot apply");
#else
  // Nothing is checked before points are evaluated: 2 million points with second derivatives
  // (0.29 GB of results) under a 200 MB limit run out of memory, which said "ask for fewer
  // levels or a smaller input".
  const auto dir = fresh_dir("hostile-at-memory");
  {
    std::ofstream points(dir / "points.csv");
    points << "face,u,v\n";
    for (int i = 0; i < 2000000; ++i) points << i % 6 << ",0.25,0.5\n";
  }
  const CliResult r = run_subdiv_with_prefix(
      "ulimit -v 200000; ", "evaluate " + kCube + " --at " + (dir / "points.csv").string() + " --derivatives 2 -o " +
                                (dir / "out.csv").string());
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(contains(r.output, "subdiv: error: out of memory while evaluating the points of"));
  CHECK(contains(r.output, "evaluate fewer points at a time (split the --at file), or ask for fewer --derivatives, or "
                           "raise the limit"));
  CHECK_FALSE(contains(r.output, "levels"));
  CHECK_FALSE(fs::exists(dir / "out.csv"));
#endif
}

TEST_CASE("a memory refusal prints its two sizes so that they differ, however close") {
#if SUBDIV_TEST_ASAN
  MESSAGE("skipped: AddressSanitizer reserves terabytes of address space, so ulimit -v cannot apply");
#else
  // --samples 500 on the cube needs some 345 MiB, a little more than the 0.4 GB limit leaves:
  // with one decimal in GiB it read "would need about 0.3 GiB, but only 0.3 GiB".
  const auto out = fresh_dir("hostile-samples-close-memory") / "big.vtp";
  const CliResult r = run_subdiv_with_prefix("ulimit -v 400000; ", "evaluate " + kCube + " --samples 500 -o " + out.string());
  INFO(r.output);
  CHECK(r.exit_code == 1);
  std::smatch sizes;
  REQUIRE(std::regex_search(r.output, sizes, std::regex("would need about ([^,]+), but only (.+) of memory is available")));
  CHECK(sizes[1].str() != sizes[2].str());
  CHECK_FALSE(fs::exists(out));
#endif
}

TEST_CASE("a sampled limit surface with face-varying data counts the data's grids before any sample") {
#if SUBDIV_TEST_ASAN
  MESSAGE("skipped: AddressSanitizer reserves terabytes of address space, so ulimit -v cannot apply");
#else
  // 24 quads with UVs, 221 x 221 points each: 0.28 GB for the positions' grid alone, which
  // passed the check, and 0.47 GB with the UV channel's, which ran out of memory half-way
  // (without a process limit: killed by the kernel).
  check_refused_within_400_mb("evaluate " + source_path("examples/meshes/textured-tube.obj") + " --samples 220 -o ",
                              fresh_dir("hostile-samples-fvar-memory") / "big.vtp",
                              {"--samples 220: 1.17e+06 sample points would need about", "ask for fewer samples per edge"});
#endif
}

TEST_CASE("a file size limit (ulimit -f) is a refusal with no file left, in every output format") {
  // 8 levels of the torus: 49 MB and more in every format; the limit is 5 MB.
  const fs::path dir = fresh_dir("hostile-file-size");
  for (const char* name : {"big.vtp", "big.obj", "big.ply", "big.pvd"}) {
    const CliResult r = run_subdiv_with_prefix(
        "ulimit -f 5000; ", "refine " + source_path("examples/meshes/torus-quads.obj") + " -l 8 -o " + (dir / name).string());
    INFO(name, r.output);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, "the disk is full or the file is larger than allowed"));
  }
  CHECK(fs::is_empty(dir));  // no output, no level folder, no temporary
}

// Bytes of a file, to show it was left as it was.
std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_CASE("-o naming the input mesh (directly, through a link, or a .pvd's level folder) is refused unless --force") {
  const fs::path dir = fresh_dir("output-is-input");
  const fs::path mesh = dir / "cube.obj";
  fs::copy_file(kCube, mesh);
  const std::string before = file_bytes(mesh);
  fs::create_symlink(mesh, dir / "link.obj");
  for (const std::string& command : {"refine " + mesh.string() + " -o " + mesh.string(),
                                     "refine " + (dir / "link.obj").string() + " -o " + mesh.string(),
                                     "refine " + mesh.string() + " -s chaikin -o " + mesh.string(),
                                     "interpolate " + mesh.string() + " -o " + mesh.string()}) {
    const CliResult r = run_subdiv(command);
    CAPTURE(command);
    CHECK(r.exit_code == 1);
    CHECK(contains(r.output, "the input mesh"));
    CHECK(contains(r.output, "--force"));
    CHECK(file_bytes(mesh) == before);
  }
  // A .pvd rewrites its level folder: an input inside it is the same loss.
  REQUIRE(run_subdiv("refine " + mesh.string() + " -l 1 -q -o " + (dir / "c.pvd").string()).exit_code == 0);
  const fs::path level = dir / "c_levels" / "level_1.vtp";
  const std::string level_before = file_bytes(level);
  const CliResult pvd = run_subdiv("refine " + level.string() + " -l 1 -o " + (dir / "c.pvd").string());
  CHECK(pvd.exit_code == 1);
  CHECK(contains(pvd.output, "rewrites the folder of the input mesh"));
  CHECK(file_bytes(level) == level_before);
  // --force writes: level 1 of the cube replaces it (24 faces).
  CHECK(run_subdiv("refine " + mesh.string() + " -l 1 -q --force -o " + mesh.string()).exit_code == 0);
  CHECK(file_bytes(mesh) != before);
  CHECK(run_subdiv("refine " + mesh.string() + " -l 1 -o " + (dir / "out.obj").string()).output.find("96 faces") !=
        std::string::npos);
}

TEST_CASE("the summary counts the faces written: hole faces are left out of both") {
  const fs::path dir = fresh_dir("hole-counts");
  {
    std::ofstream obj(dir / "strip.obj");
    obj << "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 5 4\nf 2 3 6 5\nt hole 1/0/0 1\n";
  }
  const CliResult r = run_subdiv("refine " + (dir / "strip.obj").string() + " -l 1 -o " + (dir / "out.obj").string());
  REQUIRE(r.exit_code == 0);
  // One of the two quads is a hole: its four children are not written, nor counted.
  std::ifstream written(dir / "out.obj");
  int faces = 0;
  for (std::string line; std::getline(written, line);) faces += line.rfind("f ", 0) == 0;
  CHECK(faces == 4);
  CHECK(contains(r.output, " 4 faces "));
}

TEST_CASE("refine: --tolerance without --adaptive, and --adaptive with output options it does not honour, are refused") {
  // Each was accepted and ignored: the file written was not the one asked for.
  const auto dir = fresh_dir("hostile-adaptive-options");
  check_refused("refine " + kCube + " --tolerance 0.1 -l 2", dir / "a.vtp", "--tolerance goes with --adaptive L");
  for (const std::string option : {"--arrays all", "--compression none", "--compression-level 5", "--vtp-encoding raw"}) {
    CAPTURE(option);
    const std::string name = option.substr(0, option.find(' '));
    check_refused("refine " + kCube + " --adaptive 2 " + option, dir / "b.vtp",
                  name + " goes with uniform refinement");
    check_refused("refine " + kCube + " --adaptive 2 " + option, dir / "b.vtp", "leave out " + name);
  }
  check_refused("refine " + kCube + " --adaptive 2 --normals", dir / "c.vtp",
                "--normals: adaptive refinement writes no limit normals");
  std::ofstream(dir / "lambda.txt") << "1\n1\n1\n1\n1\n1\n1\n1\n";
  check_refused("refine " + kCube + " -s catmull-clark-shape --adaptive 2 --vertex-param lambda=" +
                    (dir / "lambda.txt").string(),
                dir / "d.vtp", "--vertex-param: adaptive refinement takes a scheme parameter for the whole mesh only");
  // The defaults, given explicitly, are what --adaptive writes: taken.
  CHECK(run_subdiv("refine " + kCube + " --adaptive 2 --compression lz4 --arrays default --tolerance 0.1 -q -o " +
                   (dir / "ok.vtp").string())
            .exit_code == 0);
}
