// `subdiv evaluate` (and the commands that share its ways in and out: parameterize, analyze,
// --param) given what a hostile or unlucky user gives: outputs that are the input, FIFOs,
// links to devices or folders; points files that are no regular file; options that would be
// ignored; a full disk. Each run must exit non-zero with a message naming the file and the
// fix, within a time limit (a FIFO used to block), and leave the named paths as they were.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sys/stat.h>
#include <unistd.h>

#include "support/cli_runner.h"

using namespace subdiv::test;
namespace fs = std::filesystem;

namespace {

const std::string kCube = source_path("examples/meshes/cube.obj");

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

CliResult run_bounded(const std::string& args) { return run_subdiv_with_prefix("timeout 60 ", args); }

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("evaluate and parameterize: -o naming the input mesh or the points file is refused unless --force") {
  const auto dir = fresh_dir("hostile-evaluate-same");
  fs::copy_file(kCube, dir / "cube.obj");
  const std::string cube_text = read_text(dir / "cube.obj");
  const std::string mesh = (dir / "cube.obj").string();
  for (const std::string& how : {std::string(" --samples 2"), std::string(" --adaptive 1"), std::string(" --level-distance 1")}) {
    CAPTURE(how);
    const CliResult r = run_bounded("evaluate " + mesh + how + " -o " + mesh);
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.output, "-o '" + mesh + "' is the input mesh '" + mesh + "': writing would lose the "
                                     "control mesh; name another output, or add --force"),
                  r.output);
    CHECK(read_text(dir / "cube.obj") == cube_text);
  }
  const std::string points_text = "face,u,v\n0,0.5,0.5\n";
  std::ofstream(dir / "points.csv") << points_text;
  const std::string points = (dir / "points.csv").string();
  const CliResult r = run_bounded("evaluate " + mesh + " --at " + points + " -o " + points);
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(contains(r.output, "-o '" + points + "' is the points file --at '" + points +
                                       "': writing would lose the points; name another output, or add --force"),
                r.output);
  CHECK(read_text(dir / "points.csv") == points_text);
  // --force overwrites, as refine's does; the points were read before the file is replaced.
  const CliResult forced = run_bounded("evaluate " + mesh + " --at " + points + " --force -o " + points);
  CHECK(forced.exit_code == 0);
  CHECK(read_text(dir / "points.csv").rfind("face,u,v,x,y,z", 0) == 0);

  // parameterize takes a topological disc: two quads side by side.
  std::ofstream(dir / "disc.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\n";
  const std::string disc_text = read_text(dir / "disc.obj");
  const std::string disc = (dir / "disc.obj").string();
  const CliResult p = run_bounded("parameterize " + disc + " -o " + disc);
  CHECK(p.exit_code == 1);
  CHECK_MESSAGE(contains(p.output, "is the input mesh"), p.output);
  CHECK(read_text(dir / "disc.obj") == disc_text);
  CHECK(run_bounded("parameterize " + disc + " -q --force -o " + disc).exit_code == 0);
  CHECK(read_text(dir / "disc.obj") != disc_text);
}

TEST_CASE("evaluate: a points file that is a FIFO, a link to /dev/zero or a directory is refused at once") {
  const auto dir = fresh_dir("hostile-evaluate-points");
  REQUIRE(::mkfifo((dir / "pipe.csv").c_str(), 0600) == 0);
  fs::create_symlink("/dev/zero", dir / "zero.csv");
  fs::create_directory(dir / "folder.csv");
  struct Bad {
    const char* name;
    const char* message;
  };
  for (const Bad& b : {Bad{"pipe.csv", "it is a FIFO (named pipe); give the path of a regular points (.csv) file"},
                       Bad{"zero.csv", "it is a character device"},
                       Bad{"folder.csv", "it is a directory, not a points (.csv) file"}}) {
    CAPTURE(b.name);
    const CliResult r = run_bounded("evaluate " + kCube + " --at " + (dir / b.name).string() + " -o " +
                                    (dir / "out.csv").string());
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.output, "cannot open '" + (dir / b.name).string() + "': " + b.message), r.output);
    CHECK_FALSE(fs::exists(dir / "out.csv"));
  }
}

TEST_CASE("evaluate: an output that is a FIFO, a link to a device or a directory is refused and stays as it was") {
  // As root, -o /dev/null (or any device) was replaced by a plain file when the finished
  // temporary was renamed onto it; a link to /dev/null shows the refusal without touching /dev.
  const auto dir = fresh_dir("hostile-evaluate-outputs");
  std::ofstream(dir / "points.csv") << "face,u,v\n0,0.5,0.5\n";
  REQUIRE(::mkfifo((dir / "pipe.csv").c_str(), 0600) == 0);
  fs::create_symlink("/dev/null", dir / "null.vtp");
  fs::create_directory(dir / "folder.csv");
  const std::string at = " --at " + (dir / "points.csv").string() + " -o ";
  struct Bad {
    std::string args;
    fs::path out;
    const char* message;
  };
  for (const Bad& b : {Bad{at, dir / "pipe.csv", "is a FIFO (named pipe), which writing would replace by a plain file"},
                       Bad{" --samples 2 -o ", dir / "null.vtp", "is a character device, which writing would replace"},
                       Bad{at, dir / "folder.csv", "is a directory; name a file, in it or beside it"}}) {
    CAPTURE(b.out);
    const CliResult r = run_bounded("evaluate " + kCube + b.args + b.out.string());
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.output, "cannot write '" + b.out.string() + "': it " + b.message), r.output);
  }
  CHECK(fs::is_fifo(dir / "pipe.csv"));
  CHECK(fs::is_symlink(dir / "null.vtp"));
  CHECK(fs::is_character_file(dir / "null.vtp"));
  CHECK(fs::is_directory(dir / "folder.csv"));
  CHECK(fs::is_empty(dir / "folder.csv"));
}

TEST_CASE("evaluate: --feature-angle -5 and --derivatives without --at are refused, not ignored") {
  const auto dir = fresh_dir("hostile-evaluate-options");
  std::ofstream(dir / "points.csv") << "face,u,v\n0,0.5,0.5\n";
  const std::string at = " --at " + (dir / "points.csv").string();
  struct Bad {
    std::string args;
    fs::path out;
    const char* message;
  };
  // --feature-angle -5 was taken as "no feature angle" (the library's < 0); refine refuses it.
  for (const Bad& b : {Bad{at + " --feature-angle -5", dir / "a.csv", "--feature-angle: Value -5 not in range"},
                       Bad{" --samples 2 --derivatives 2", dir / "b.vtp", "--derivatives goes with --at POINTS.csv"},
                       Bad{" --adaptive 1 --derivatives 0", dir / "c.vtp", "--derivatives goes with --at POINTS.csv"},
                       Bad{at + " --approximate bezier --derivatives 2", dir / "d.csv",
                           "--derivatives goes with --at POINTS.csv"}}) {
    CAPTURE(b.args);
    const CliResult r = run_bounded("evaluate " + kCube + b.args + " -o " + b.out.string());
    CHECK(r.exit_code != 0);
    CHECK_MESSAGE(contains(r.output, b.message), r.output);
    CHECK_FALSE(fs::exists(b.out));
  }
  CHECK(run_bounded("evaluate " + kCube + at + " --derivatives 0 -o " + (dir / "ok.csv").string()).exit_code == 0);
}

TEST_CASE("evaluate: a sequence whose last scheme cannot take the faces its head makes is refused as refine refuses it") {
  // Loop after Catmull-Clark's quads failed at the first point, as "face 0 at (u, v) = (1, 1):
  // the scheme refines triangles", naming neither the scheme nor the fix.
  const auto dir = fresh_dir("hostile-evaluate-sequence");
  std::ofstream(dir / "points.csv") << "face,u,v\n0,0.5,0.5\n";
  for (const std::string& how : {" --at " + (dir / "points.csv").string() + " -o " + (dir / "out.csv").string(),
                                 " --samples 2 -o " + (dir / "out.vtp").string()}) {
    CAPTURE(how);
    const CliResult r = run_bounded("evaluate " + kCube + " -s catmull-clark:1,loop" + how);
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.output, "scheme 'loop' needs triangles, but face 0 of level 1 (made by the schemes before "
                                     "it) has 4 vertices"),
                  r.output);
  }
  CHECK_FALSE(fs::exists(dir / "out.csv"));
  CHECK_FALSE(fs::exists(dir / "out.vtp"));
}

TEST_CASE("a --param given twice is refused, not decided by its order") {
  const auto dir = fresh_dir("hostile-param-twice");
  for (const char* command : {"refine ", "evaluate "}) {
    CAPTURE(command);
    const std::string args = std::string(command) + kCube + " -p triangles=smooth -p triangles=catmark" +
                             (std::string(command) == "refine " ? " -l 1" : " --samples 2");
    const CliResult r = run_bounded(args + " -o " + (dir / "out.obj").string());
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.output, "--param 'triangles' is given twice ('triangles=smooth' and "
                                     "'triangles=catmark'); give it once"),
                  r.output);
    CHECK_FALSE(fs::exists(dir / "out.obj"));
  }
}

TEST_CASE("evaluate and analyze: a file size limit (ulimit -f) is a refusal naming the fix, with no file left") {
  // The .csv was written through an unchecked stream whose last buffer is flushed on
  // destruction: with nothing allowed on disk an empty file was renamed into place, exit 0.
  const auto dir = fresh_dir("hostile-evaluate-file-size");
  std::ofstream(dir / "points.csv") << "face,u,v\n0,0.5,0.5\n";
  const std::string at = " --at " + (dir / "points.csv").string();
  for (const std::string& args :
       {"evaluate " + kCube + at + " -o " + (dir / "out.csv").string(),
        "evaluate " + kCube + at + " --approximate bezier -o " + (dir / "out.csv").string(),
        "analyze catmull-clark --valence 3 --json " + (dir / "out.json").string(),
        "analyze catmull-clark --valence 3 --svg " + (dir / "out.svg").string()}) {
    CAPTURE(args);
    const CliResult r = run_subdiv_with_prefix("ulimit -f 0; ", args);
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.output, "the disk is full or the file is larger than allowed"), r.output);
  }
  for (const auto& e : fs::directory_iterator(dir)) CHECK_MESSAGE(e.path().filename() == "points.csv", e.path());
}

TEST_CASE("evaluate --approximate bezier --bezier-net: a failed -o leaves no control nets behind") {
  // The nets are written into a temporary that becomes the .vtu only once -o is in place.
  const auto dir = fresh_dir("hostile-evaluate-nets");
  fs::create_directory(dir / "folder.obj");
  const CliResult r = run_bounded("evaluate " + kCube + " --approximate bezier --samples 2 -o " +
                                  (dir / "folder.obj").string() + " --bezier-net " + (dir / "nets.vtu").string());
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(contains(r.output, "it is a directory"), r.output);
  CHECK_FALSE(fs::exists(dir / "nets.vtu"));
  size_t left = 0;
  for (const auto& entry : fs::directory_iterator(dir)) left += entry.path().filename() != "folder.obj";
  CHECK(left == 0);  // no temporary either
  const CliResult ok = run_bounded("evaluate " + kCube + " --approximate bezier --samples 2 -o " +
                                   (dir / "ok.obj").string() + " --bezier-net " + (dir / "nets.vtu").string());
  CHECK(ok.exit_code == 0);
  CHECK(fs::exists(dir / "ok.obj"));
  CHECK(read_text(dir / "nets.vtu").find("VTKFile") != std::string::npos);
}

TEST_CASE("evaluate --approximate: every output path is refused before any patch is built") {
  // A --bezier-net in a missing folder, in a read-only place or naming a folder, and an -o of
  // a format no writer has, were reported only after the patches, samples and distances were
  // made (13 s on the torus, --samples 300).
  const auto dir = fresh_dir("hostile-evaluate-paths");
  fs::create_directory(dir / "folder.vtu");
  std::ofstream(dir / "points.csv") << "face,u,v\n0,0.5,0.5\n";
  // As root a folder without write permission is writable; /sys is not, even to root.
  fs::path read_only = dir / "read-only";
  fs::create_directory(read_only);
  fs::permissions(read_only, fs::perms::owner_read | fs::perms::owner_exec);
  if (::geteuid() == 0) read_only = "/sys";
  const std::string at = " --at " + (dir / "points.csv").string();
  struct Bad {
    std::string args;
    std::string message;
  };
  const std::string nets = " --approximate bezier --samples 2 -o " + (dir / "out.vtp").string() + " --bezier-net ";
  for (const Bad& b :
       {Bad{nets + (dir / "missing" / "n.vtu").string(), "does not exist; create it first"},
        Bad{nets + (dir / "folder.vtu").string(), "it is a directory; name a file, in it or beside it"},
        Bad{nets + (read_only / "n.vtu").string(), "cannot create a temporary file in its directory"},
        Bad{" --approximate bezier" + at + " -o " + (dir / "missing" / "out.csv").string() + " --bezier-net " +
                (dir / "n.vtu").string(),
            "does not exist; create it first"},
        Bad{" --approximate gregory" + at + " -o " + (read_only / "out.csv").string(),
            "cannot create a temporary file in its directory"},
        Bad{" --approximate bezier --samples 2 -o " + (dir / "out.vtu").string(), "unknown mesh format '.vtu'"}}) {
    CAPTURE(b.args);
    const CliResult r = run_bounded("evaluate " + kCube + b.args);
    CHECK(r.exit_code == 1);
    CHECK_MESSAGE(contains(r.output, b.message), r.output);
    CHECK_MESSAGE(!contains(r.output, "against the exact limit"), r.output);  // the work's summary: none was done
  }
  size_t left = 0;
  for (const auto& entry : fs::directory_iterator(dir)) left += !contains("folder.vtu points.csv read-only", entry.path().filename().string());
  CHECK(left == 0);
  fs::permissions(dir / "read-only", fs::perms::owner_all);
}

TEST_CASE("evaluate --approximate: a polyline beside the faces changes nothing") {
  // The polyline's vertices are no patch's corner, but their limit ("isolated vertex") was
  // required to be exact, and the whole mesh refused.
  const auto dir = fresh_dir("hostile-evaluate-polyline");
  const std::string quads = "v 0 0 0\nv 1 0 0\nv 1 1 0.5\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\n";
  std::ofstream(dir / "faces.obj") << quads;
  std::ofstream(dir / "with-line.obj") << quads << "v 3 3 3\nv 4 4 4\nl 7 8\n";
  std::ofstream(dir / "points.csv") << "face,u,v\n0,0.5,0.5\n1,0.25,0.75\n0,0,0\n";
  for (const char* kind : {"bezier", "gregory"}) {
    CAPTURE(kind);
    std::string outputs[2];
    for (int with_line = 0; with_line < 2; ++with_line) {
      const fs::path out = dir / (std::string(kind) + (with_line ? "-line.csv" : ".csv"));
      const CliResult r = run_bounded("evaluate " + (dir / (with_line ? "with-line.obj" : "faces.obj")).string() +
                                      " --approximate " + kind + " --at " + (dir / "points.csv").string() + " -o " +
                                      out.string());
      CHECK_MESSAGE(r.exit_code == 0, r.output);
      outputs[with_line] = read_text(out);
    }
    CHECK(outputs[0].find("face,u,v,x,y,z") == 0);
    CHECK(outputs[0] == outputs[1]);
  }
}

TEST_CASE("evaluate --samples: a point the surface refuses names the mesh file, the face and the fix") {
  // A bipyramid whose two poles have valence 600, above the analysis' 512: its samples at the
  // poles are refused; the message must say which file, as the preparation's messages do.
  const auto dir = fresh_dir("hostile-evaluate-valence");
  const fs::path mesh = dir / "bipyramid-600.obj";
  {
    std::ofstream out(mesh);
    const int n = 600;
    out << "v 0 0 1\n";
    for (int i = 0; i < n; ++i) out << "v " << std::cos(2 * std::numbers::pi * i / n) << ' ' << std::sin(2 * std::numbers::pi * i / n) << " 0\n";
    out << "v 0 0 -1\n";
    for (int i = 0; i < n; ++i) {
      const int a = i + 2, b = (i + 1) % n + 2;
      out << "f 1 " << a << ' ' << b << "\nf " << n + 2 << ' ' << b << ' ' << a << '\n';
    }
  }
  const CliResult r = run_bounded("evaluate " + mesh.string() + " -s loop --samples 2 -o " + (dir / "out.obj").string());
  CHECK(r.exit_code == 1);
  CHECK_MESSAGE(contains(r.output, "subdiv: error: " + mesh.string() + ": face "), r.output);
  CHECK_MESSAGE(contains(r.output, "valence 600"), r.output);
  CHECK_MESSAGE(contains(r.output, "bring it within 512"), r.output);
  CHECK_FALSE(fs::exists(dir / "out.obj"));
}

TEST_CASE("evaluate --samples on a surface without a normal somewhere warns with the count and the first place") {
  // A pillow (two quads back to back) folds flat along its edges: du x dv = 0 there. The
  // Normals were written as (0, 0, 0) without a word.
  const auto dir = fresh_dir("hostile-evaluate-normals");
  std::ofstream(dir / "pillow.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 4 3 2 1\n";
  for (const char* how : {" --samples 4 -o ", " --approximate gregory --samples 4 -o "}) {
    CAPTURE(how);
    const fs::path out = dir / "pillow-limit.vtp";
    const CliResult r = run_bounded("evaluate " + (dir / "pillow.obj").string() + how + out.string());
    CHECK_MESSAGE(r.exit_code == 0, r.output);
    CHECK_MESSAGE(contains(r.output, "subdiv: warning: the limit surface has no normal at "), r.output);
    CHECK_MESSAGE(contains(r.output, "points (the first at face "), r.output);
    // The file reads back, zero normals and all.
    const CliResult back = run_bounded("refine " + out.string() + " -l 0 -o " + (dir / "back.obj").string());
    CHECK_MESSAGE(back.exit_code == 0, back.output);
  }
  const CliResult cube = run_bounded("evaluate " + kCube + " --samples 4 -o " + (dir / "cube.vtp").string());
  CHECK(cube.exit_code == 0);
  CHECK_FALSE(contains(cube.output, "warning"));
}
