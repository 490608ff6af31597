// `subdiv evaluate` (and the commands that share its ways in and out: parameterize, analyze,
// --param) given what a hostile or unlucky user gives: outputs that are the input, FIFOs,
// links to devices or folders; points files that are no regular file; options that would be
// ignored; a full disk. Each run must exit non-zero with a message naming the file and the
// fix, within a time limit (a FIFO used to block), and leave the named paths as they were.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>

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
