// Progress of reading and writing mesh files (issue 31, item 4): the share done starts at
// 0, never goes back, ends at 1, moves in between for a large file, and is told a few hundred
// times at most however large the file (io_progress.h).
#include <doctest/doctest.h>

#include <vector>

#include "framework/io/mesh_read.h"
#include "framework/io/mesh_write.h"
#include "unit/io/io_test_support.h"

using namespace subdiv;
using namespace subdiv::test;

namespace {

MeshData quad_grid(int n) {
  MeshData m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.insert(m.positions.end(), {double(i), double(j), 0.0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Index a = j * (n + 1) + i;
      m.face_vertices.insert(m.face_vertices.end(), {a, a + 1, a + n + 2, a + n + 1});
      m.face_offsets.push_back(Index(m.face_vertices.size()));
    }
  return m;
}

void check_shares(const std::vector<double>& shares, bool moves) {
  REQUIRE(shares.size() >= 2);
  CHECK(shares.front() == 0.0);
  CHECK(shares.back() == 1.0);
  for (std::size_t i = 1; i < shares.size(); ++i) CHECK(shares[i] >= shares[i - 1]);
  CHECK(shares.size() <= 300);
  bool between = false;
  for (double s : shares) between = between || (s > 0 && s < 1);
  if (moves) CHECK(between);
}

}  // namespace

TEST_CASE("writing OBJ, OFF, PLY and STL reports a share that starts at 0, moves, never goes back and ends at 1") {
  TempDir dir;
  const MeshData mesh = quad_grid(300);  // 90,000 quads
  for (const char* ext : {".obj", ".off", ".ply", ".stl"}) {
    const std::string format = ext;
    CAPTURE(format);
    std::vector<double> shares;
    write_mesh(dir / ("grid" + format), mesh, [&shares](double done) { shares.push_back(done); });
    check_shares(shares, true);
  }
}

TEST_CASE("reading a large OBJ or OFF reports a moving share; every format starts at 0 and ends at 1") {
  TempDir dir;
  const MeshData mesh = quad_grid(300);
  for (const char* ext : {".obj", ".off", ".ply", ".stl"}) {
    const std::string format = ext;
    CAPTURE(format);
    write_mesh(dir / ("grid" + format), mesh);
    std::vector<double> shares;
    const MeshData back = read_mesh(dir / ("grid" + format), [&shares](double done) { shares.push_back(done); });
    CHECK(back.face_count() == (format == ".stl" ? 2 * mesh.face_count() : mesh.face_count()));
    check_shares(shares, format == ".obj" || format == ".off");
  }
}

TEST_CASE("a read that fails still ends its progress at 1 (a front-end's bar is closed)") {
  TempDir dir;
  write_text(dir / "bad.obj", "v 0 0 0\nf 1 2 3\n");
  std::vector<double> shares;
  CHECK_THROWS_AS(read_mesh(dir / "bad.obj", [&shares](double done) { shares.push_back(done); }), Error);
  REQUIRE(!shares.empty());
  CHECK(shares.back() == 1.0);
}
