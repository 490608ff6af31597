// User text in the library's messages is escaped in the message itself (issue 33,
// framework/util/quoted_text.h), not only by the front-ends before printing: a NUL in a
// file, array or scheme name would otherwise end the C string what() returns, cutting the
// message (its reason and its fix) short, and an ESC would reach any program that shows it
// (ParaView's output window, a log). Each case checks the escaped name, that the message
// goes on after it, and that no control byte is left.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "framework/io/mesh_read.h"
#include "framework/io/mesh_validate.h"
#include "framework/pipeline/refine_pipeline.h"
#include "framework/scheme/scheme_registry.h"
#include "framework/util/error.h"
#include "support/mesh_data_of.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

const std::string kHostile("n\0m\x1b[2J", 8);  // a NUL and a terminal escape
const std::string kEscaped = "n\\x00m\\x1b[2J";

bool has_control_byte(const std::string& s) {
  for (const char c : s) {
    const auto b = static_cast<unsigned char>(c);
    if ((b < 0x20 && c != '\n' && c != '\t') || b == 0x7F) return true;
  }
  return false;
}

// The message as a C caller sees it (what()), which must be whole: `tail` follows the name.
void check_whole_and_escaped(const Error& e, const std::string& tail) {
  const std::string message = e.what();
  INFO(message);
  CHECK_FALSE(has_control_byte(message));
  const size_t name = message.find(kEscaped);
  REQUIRE(name != std::string::npos);
  CHECK(message.find(tail, name) != std::string::npos);
}

template <class Body>
void check_refusal(Body&& body, const std::string& tail) {
  try {
    body();
    FAIL("no subdiv::Error");
  } catch (const Error& e) {
    check_whole_and_escaped(e, tail);
  }
}

}  // namespace

TEST_CASE("a NUL and an ESC in a file name: the message is whole and escaped") {
  check_refusal([] { (void)read_mesh(kHostile + ".obj"); }, "no such file");
  // A real file whose name holds an ESC (a NUL cannot be in a file name), refused for its content.
  const auto dir = std::filesystem::temp_directory_path() / "subdiv-quoted-messages";
  std::filesystem::create_directories(dir);
  const std::string esc_name = "e\x1b[2J.obj";
  std::ofstream(dir / esc_name) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n";
  try {
    (void)read_mesh(dir / esc_name);
    FAIL("no subdiv::Error");
  } catch (const Error& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK_FALSE(has_control_byte(message));
    CHECK(message.find("e\\x1b[2J.obj") != std::string::npos);
    CHECK(message.find("got 'x'") != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("a NUL and an ESC in an array name: the message is whole and escaped") {
  MeshData mesh = test::mesh_data(test::cube());
  mesh.point_data.push_back({kHostile, 1, {1.0, 2.0}, false});  // 2 values for 8 points
  check_refusal([&] { validate_mesh_data(mesh, "cube"); }, "has 2 values");
  // A note of the pipeline about an array it leaves out (a point array of normals).
  RefineRequest r;
  r.mesh = test::mesh_data(test::cube());
  r.mesh.point_data.push_back({kHostile, 3, std::vector<double>(24, 0.5), false, ArrayRole::Normals});
  r.mesh_name = "cube";
  r.scheme.text = "catmull-clark";
  r.levels = 1;
  const RefineResult result = refine_mesh(r);
  bool noted = false;
  for (const std::string& note : result.notes) {
    INFO(note);
    CHECK_FALSE(has_control_byte(note));
    noted = noted || (note.find(kEscaped) != std::string::npos && note.find("holds normals") != std::string::npos);
  }
  CHECK(noted);
}

TEST_CASE("a NUL and an ESC in a scheme name: the message is whole and escaped") {
  check_refusal([] { (void)load_scheme(kHostile); }, "the schemes are");
}

}  // namespace subdiv
