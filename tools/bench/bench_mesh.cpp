#include "bench_mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace subdiv_bench {
namespace {

std::uint64_t mix64(std::uint64_t x) {  // splitmix64 finaliser
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// A deterministic value in [-0.5, 0.5) for vertex i, channel c.
double jitter(std::int64_t i, int c) {
  return double(mix64(std::uint64_t(i) * 3 + std::uint64_t(c)) >> 11) * 0x1.0p-53 - 0.5;
}

void add_face(Mesh& m, std::initializer_list<std::int32_t> v) {
  m.face_vertices.insert(m.face_vertices.end(), v);
  m.face_sizes.push_back(std::int32_t(v.size()));
  m.face_offsets.push_back(std::int32_t(m.face_vertices.size()));
}

constexpr double kMajor = 1.0, kMinor = 0.4;

// Point on the torus at parameters (u, v) in units of whole turns.
void torus_point(double u, double v, double* p) {
  const double a = 2 * std::numbers::pi * u, b = 2 * std::numbers::pi * v;
  p[0] = (kMajor + kMinor * std::cos(b)) * std::cos(a);
  p[1] = (kMajor + kMinor * std::cos(b)) * std::sin(a);
  p[2] = kMinor * std::sin(b);
}

// nu x nv grid on the torus with nu ~ 2.5 nv (cells roughly square), nu * nv ~ cells.
void torus_grid(std::int64_t cells, int& nu, int& nv) {
  nv = std::max(3, int(std::lround(std::sqrt(double(cells) / 2.5))));
  nu = std::max(3, int(std::lround(double(cells) / nv)));
}

void finish(Mesh& m, double spacing) {
  // Small deterministic jitter so the surface has no exact symmetries.
  const double amp = 0.1 * spacing;
  for (std::int64_t i = 0; i < m.vertex_count; ++i)
    for (int c = 0; c < 3; ++c) m.xyz[3 * i + c] += amp * jitter(i, c);
}

Mesh make_torus(int nu, int nv) {
  Mesh m;
  m.name = "torus";
  m.vertex_count = nu * nv;
  m.xyz.resize(3 * size_t(m.vertex_count));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) torus_point(double(i) / nu, double(j) / nv, &m.xyz[3 * (size_t(i) * nv + j)]);
  m.face_vertices.reserve(4 * size_t(nu) * nv);
  m.face_sizes.reserve(size_t(nu) * nv);
  m.face_offsets.reserve(size_t(nu) * nv + 1);
  auto id = [&](int i, int j) { return std::int32_t((i % nu) * nv + (j % nv)); };
  // (i, j) -> (i+1, j) -> (i+1, j+1) -> (i, j+1) is counter-clockwise seen from outside.
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) add_face(m, {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  finish(m, 2 * std::numbers::pi * kMinor / nv);
  return m;
}

Mesh make_torus(std::int64_t target_faces) {
  int nu, nv;
  torus_grid(target_faces, nu, nv);
  return make_torus(nu, nv);
}

// The torus grid cut into triangles along the (i, j)-(i+1, j+1) diagonals.
Mesh make_tri_torus(std::int64_t target_faces) {
  int nu, nv;
  torus_grid((target_faces + 1) / 2, nu, nv);
  Mesh m = make_torus(nu, nv);  // the same grid, its quads replaced below
  m.name = "tri-torus";
  m.face_vertices.clear();
  m.face_sizes.clear();
  m.face_offsets.assign(1, 0);
  auto id = [&](int i, int j) { return std::int32_t((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      add_face(m, {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      add_face(m, {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// The triangulated torus with each triangle split into three quads around its centre.
Mesh make_torus_ev(std::int64_t target_faces) {
  int nu, nv;
  torus_grid((target_faces + 5) / 6, nu, nv);
  const std::int64_t cells = std::int64_t(nu) * nv;
  // Vertex blocks: grid vertices [0, cells), edge midpoints [cells, 4 cells) (3 edges per
  // cell: along u, along v, diagonal), triangle centres [4 cells, 6 cells).
  Mesh m;
  m.name = "torus-ev";
  m.vertex_count = std::int32_t(6 * cells);
  m.xyz.resize(3 * size_t(m.vertex_count));
  auto gv = [&](int i, int j) { return std::int32_t(((i + nu) % nu) * nv + (j + nv) % nv); };
  auto cell = [&](int i, int j) { return std::int64_t(((i + nu) % nu)) * nv + (j + nv) % nv; };
  auto mid_u = [&](int i, int j) { return std::int32_t(cells + 3 * cell(i, j) + 0); };  // (i,j)-(i+1,j)
  auto mid_v = [&](int i, int j) { return std::int32_t(cells + 3 * cell(i, j) + 1); };  // (i,j)-(i,j+1)
  auto mid_d = [&](int i, int j) { return std::int32_t(cells + 3 * cell(i, j) + 2); };  // (i,j)-(i+1,j+1)
  auto centre = [&](int i, int j, int t) { return std::int32_t(4 * cells + 2 * cell(i, j) + t); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = double(i) / nu, v = double(j) / nv, du = 1.0 / nu, dv = 1.0 / nv;
      torus_point(u, v, &m.xyz[3 * size_t(gv(i, j))]);
      torus_point(u + du / 2, v, &m.xyz[3 * size_t(mid_u(i, j))]);
      torus_point(u, v + dv / 2, &m.xyz[3 * size_t(mid_v(i, j))]);
      torus_point(u + du / 2, v + dv / 2, &m.xyz[3 * size_t(mid_d(i, j))]);
      torus_point(u + 2 * du / 3, v + dv / 3, &m.xyz[3 * size_t(centre(i, j, 0))]);
      torus_point(u + du / 3, v + 2 * dv / 3, &m.xyz[3 * size_t(centre(i, j, 1))]);
    }
  m.face_vertices.reserve(24 * size_t(cells));
  m.face_sizes.reserve(6 * size_t(cells));
  m.face_offsets.reserve(6 * size_t(cells) + 1);
  // Triangle (a, b, c) counter-clockwise with edge midpoints ab, bc, ca and centre g gives
  // quads (a, ab, g, ca), (b, bc, g, ab), (c, ca, g, bc).
  auto tri = [&](std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t ab, std::int32_t bc,
                 std::int32_t ca, std::int32_t g) {
    add_face(m, {a, ab, g, ca});
    add_face(m, {b, bc, g, ab});
    add_face(m, {c, ca, g, bc});
  };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      // Lower triangle (i,j), (i+1,j), (i+1,j+1); upper (i,j), (i+1,j+1), (i,j+1).
      tri(gv(i, j), gv(i + 1, j), gv(i + 1, j + 1), mid_u(i, j), mid_v(i + 1, j), mid_d(i, j), centre(i, j, 0));
      tri(gv(i, j), gv(i + 1, j + 1), gv(i, j + 1), mid_d(i, j), mid_u(i, j + 1), mid_v(i, j), centre(i, j, 1));
    }
  finish(m, 2 * std::numbers::pi * kMinor / nv / 3);
  return m;
}

// A cube with n x n quads per side, projected onto the unit sphere.
Mesh make_cube_sphere(std::int64_t target_faces) {
  const int n = std::max(1, int(std::lround(std::sqrt(double(target_faces) / 6))));
  Mesh m;
  m.name = "cube-sphere";
  // Lattice points on the cube surface, numbered by their sorted lattice keys, so the
  // points shared by two or three sides get one index.
  const std::int64_t side = std::int64_t(n) + 1;
  auto key = [&](int x, int y, int z) { return (std::int64_t(x) * side + y) * side + z; };
  std::vector<std::int64_t> keys;
  keys.reserve(6 * size_t(side) * side);
  for (int a = 0; a < 3; ++a)
    for (int s = 0; s < 2; ++s)
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          int p[3];
          p[a] = s ? n : 0;
          p[(a + 1) % 3] = i;
          p[(a + 2) % 3] = j;
          keys.push_back(key(p[0], p[1], p[2]));
        }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  auto index_of = [&](int x, int y, int z) {
    return std::int32_t(std::lower_bound(keys.begin(), keys.end(), key(x, y, z)) - keys.begin());
  };
  m.vertex_count = std::int32_t(keys.size());
  m.xyz.resize(3 * keys.size());
  for (size_t k = 0; k < keys.size(); ++k) {
    const double x = double(keys[k] / (side * side)) - n / 2.0;
    const double y = double(keys[k] / side % side) - n / 2.0;
    const double z = double(keys[k] % side) - n / 2.0;
    const double r = std::sqrt(x * x + y * y + z * z);
    m.xyz[3 * k] = x / r;
    m.xyz[3 * k + 1] = y / r;
    m.xyz[3 * k + 2] = z / r;
  }
  m.face_vertices.reserve(24 * size_t(n) * n);
  for (int a = 0; a < 3; ++a)
    for (int s = 0; s < 2; ++s)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto at = [&](int di, int dj) {
            int p[3];
            p[a] = s ? n : 0;
            p[(a + 1) % 3] = i + di;
            p[(a + 2) % 3] = j + dj;
            return index_of(p[0], p[1], p[2]);
          };
          // e_{a+1} x e_{a+2} = e_a: the (i, j) order faces +e_a, i.e. outwards when s = 1.
          if (s)
            add_face(m, {at(0, 0), at(1, 0), at(1, 1), at(0, 1)});
          else
            add_face(m, {at(0, 0), at(0, 1), at(1, 1), at(1, 0)});
        }
  finish(m, 2.0 / n);
  return m;
}

}  // namespace

std::vector<std::string> mesh_kinds() { return {"torus", "torus-ev", "cube-sphere", "tri-torus"}; }

bool mesh_is_triangles(const std::string& kind) { return kind == "tri-torus"; }

Mesh make_mesh(const std::string& kind, std::int64_t target_faces) {
  if (target_faces < 1 || target_faces > 200'000'000)
    throw std::invalid_argument("--faces must be between 1 and 200000000");
  if (kind == "torus") return make_torus(target_faces);
  if (kind == "torus-ev") return make_torus_ev(target_faces);
  if (kind == "cube-sphere") return make_cube_sphere(target_faces);
  if (kind == "tri-torus") return make_tri_torus(target_faces);
  throw std::invalid_argument("unknown mesh '" + kind + "' (torus, torus-ev, cube-sphere, tri-torus)");
}

}  // namespace subdiv_bench
