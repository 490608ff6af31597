#pragma once
// Shared helpers for the io tests: a scratch directory, file helpers, sample meshes and a
// way to capture the message of a subdiv::Error.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "framework/io/mesh_data.h"
#include "framework/util/error.h"

namespace subdiv::test {

namespace fs = std::filesystem;

// A fresh directory under the system temp directory, removed with everything in it.
class TempDir {
public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            ("subdiv_io_test_" + std::to_string(std::random_device{}()) + "_" +
             std::to_string(counter++));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  fs::path operator/(const std::string& name) const { return path_ / name; }
  const fs::path& path() const { return path_; }

  // Every entry directly or indirectly inside, as paths relative to the directory.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(path_))
      names.push_back(fs::relative(e.path(), path_).generic_string());
    std::sort(names.begin(), names.end());
    return names;
  }

private:
  fs::path path_;
};

inline void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
}

inline std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The message of the subdiv::Error that `f` throws, or "<no error>".
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "<no error>";
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Coordinates chosen to expose any float rounding or short printing: none is exactly a
// float. Faces: a quad, two triangles and a pentagon sharing edges; a polyline; tags.
inline MeshData sample_mesh() {
  MeshData m;
  m.positions = {0.1,  0.2,        1.0 / 3.0, 1.0000000000000002, -0.3, 1e-17,
                 2.5,  1.7,        -0.7,      -123456.78901234567, 0.5,  0.25,
                 3.14159265358979, 2.718281828459045, 1e10 / 3,  0.6, -0.6, 0.0,
                 7.1,  7.2,        7.3};
  m.face_offsets = {0, 4, 7, 10, 15};
  m.face_vertices = {0, 1, 2, 3, 0, 3, 4, 1, 5, 2, 3, 2, 5, 6, 4};
  m.line_offsets = {0, 3};
  m.line_vertices = {6, 5, 0};
  m.creases = {{0, 1, 10.0}, {2, 3, 0.5}};
  m.corners = {{4, 2.25}};
  return m;
}

// The unit cube, CCW outward: a closed manifold for formats that need one (STL, OM).
inline MeshData cube_mesh() {
  MeshData m;
  m.positions = {-0.5, -0.5, -0.5, 0.5, -0.5, -0.5, 0.5, 0.5, -0.5, -0.5, 0.5, -0.5,
                 -0.5, -0.5, 0.5,  0.5, -0.5, 0.5,  0.5, 0.5, 0.5,  -0.5, 0.5, 0.5};
  m.face_offsets = {0, 4, 8, 12, 16, 20, 24};
  m.face_vertices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 0, 4, 7, 3, 1, 2, 6, 5};
  return m;
}

inline void check_same_positions(const MeshData& a, const MeshData& b, double tolerance) {
  REQUIRE(a.positions.size() == b.positions.size());
  for (size_t i = 0; i < a.positions.size(); ++i)
    CHECK(std::abs(a.positions[i] - b.positions[i]) <= tolerance * (1 + std::abs(a.positions[i])));
}

inline void check_same_faces(const MeshData& a, const MeshData& b) {
  CHECK(a.face_offsets == b.face_offsets);
  CHECK(a.face_vertices == b.face_vertices);
}

}  // namespace subdiv::test
