#pragma once
// Helpers for the surface analysis tests: a mesh with one vertex of valence n (the
// analysis' own synthetic patch, so the rest is regular) with random 3D positions, and its
// ring read off the mesh the way Halstead, Kass & DeRose 1993 write it (e_j: edge neighbours CCW, f_j: the
// face-diagonal points between e_j and e_{j+1}).
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "framework/analysis/surface/local_patch.h"
#include "framework/topology/level.h"

namespace subdiv::test {

using Vec3 = std::array<double, 3>;

inline const double kPi = std::acos(-1.0);

struct RandomPatch {
  Level level;
  std::vector<double> positions;  // xyz
};

// The synthetic patch of valence n with the plane positions perturbed in 3D.
inline RandomPatch random_patch(PatchCells cells, int n, unsigned seed, int rings = 5, bool boundary = false) {
  LocalConfig c;
  c.valence = n;
  c.boundary = boundary;
  Patch p = make_vertex_patch(cells, c, rings);
  RandomPatch r{p.level, {}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (Index v = 0; v < p.level.vertex_count; ++v)
    r.positions.insert(r.positions.end(), {p.xy[size_t(2 * v)] + u(rng), p.xy[size_t(2 * v + 1)] + u(rng), u(rng)});
  return r;
}

inline Vec3 at(const std::vector<double>& p, Index v) { return {p[size_t(3 * v)], p[size_t(3 * v + 1)], p[size_t(3 * v + 2)]}; }

inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 unit(const Vec3& a) {
  const double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}
inline double distance(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// e_j: the other end of ring edge j; f_j: in ring face j (between ring edges j and j+1) of
// a quad, the corner opposite v.
inline std::vector<Index> ring_neighbours(const Level& L, Index v) {
  std::vector<Index> out;
  for (Index e : L.ring_edges(v)) out.push_back(L.other_end(e, v));
  return out;
}
inline std::vector<Index> face_diagonals(const Level& L, Index v) {
  std::vector<Index> out;
  const auto faces = L.ring_faces(v);
  for (size_t i = 0; i < faces.size(); ++i) {
    const auto corners = L.face(faces[i]);
    const int c = L.vertex_face_corner[size_t(L.vertex_face_offsets[v]) + i];
    out.push_back(corners[size_t((c + 2) % int(corners.size()))]);
  }
  return out;
}

// Halstead, Kass & DeRose 1993 at a Catmull-Clark vertex of valence n with edge neighbours
// e_j and face-diagonal points f_j: the limit point (n^2 v + 4 sum e_j + sum f_j)/(n (n + 5)),
// and the unit normal C_2 x C_3 with C_2 = sum_j A_n cos(2 pi j/n) e_j + (cos(2 pi j/n) +
// cos(2 pi (j+1)/n)) f_j, C_3 the same with e_{j+1}, f_{j+1}, and
// A_n = 1 + cos(2 pi/n) + cos(pi/n) sqrt(2 (9 + cos(2 pi/n))).
struct CatmullClarkLimit {
  Vec3 point, normal;
};
inline CatmullClarkLimit catmull_clark_limit(const std::vector<double>& P, Index v, const std::vector<Index>& e,
                                             const std::vector<Index>& f) {
  const int n = int(e.size());
  CatmullClarkLimit out{};
  for (int i = 0; i < 3; ++i) {
    double sum = double(n) * n * P[size_t(3 * v + i)];
    for (int j = 0; j < n; ++j) sum += 4 * at(P, e[size_t(j)])[size_t(i)] + at(P, f[size_t(j)])[size_t(i)];
    out.point[size_t(i)] = sum / (double(n) * (n + 5));
  }
  const double c = std::cos(2 * kPi / n);
  const double A = 1 + c + std::cos(kPi / n) * std::sqrt(2 * (9 + c));
  Vec3 c2{0, 0, 0}, c3{0, 0, 0};
  for (int j = 0; j < n; ++j) {
    const double ce = A * std::cos(2 * kPi * j / n);
    const double cf = std::cos(2 * kPi * j / n) + std::cos(2 * kPi * (j + 1) / n);
    const Vec3 ej = at(P, e[size_t(j)]), fj = at(P, f[size_t(j)]);
    const Vec3 ej1 = at(P, e[size_t((j + 1) % n)]), fj1 = at(P, f[size_t((j + 1) % n)]);
    for (int i = 0; i < 3; ++i) {
      c2[size_t(i)] += ce * ej[size_t(i)] + cf * fj[size_t(i)];
      c3[size_t(i)] += ce * ej1[size_t(i)] + cf * fj1[size_t(i)];
    }
  }
  out.normal = unit(cross(c2, c3));
  return out;
}

inline std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "subdivkit-analysis-tests";
  std::filesystem::create_directories(dir);
  const auto file = dir / name;
  std::ofstream(file) << text;
  return file;
}

}  // namespace subdiv::test
