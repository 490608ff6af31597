// subdiv-render MESH OUT.png [--azimuth DEG] [--elevation DEG] [--size PIXELS] [--cage MESH]
//               [--checker N] [--color-by ARRAY] [--edges 0|1]
//
// Draws a mesh (any format `subdiv` reads) into a PNG with a small software rasterizer:
// orthographic view, two-sided flat shading, face edges in a darker tone, and optionally a
// control cage as thick lines; polylines (OBJ 'l') of either as lines. It needs no display and no GPU, so the figures in docs/ can
// be rendered on a headless build machine (Debian's VTK renders only through X or OSMesa).
// --checker N paints the mesh's texture coordinates (face-varying, e.g. OBJ vt, or per
// point) as an N x N checkerboard, interpolated across each triangle, to show UVs and seams.
// --color-by ARRAY paints a scalar point array (e.g. limit_distance, level_distance) with the
// viridis colour map from 0 to its largest value, interpolated across each triangle, draws
// the map as a bar on the right (0 at the bottom) and prints the range; --edges 0 leaves out
// the face edges (for finely sampled meshes).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>
#include <zlib.h>

#include <fmt/format.h>

#include "framework/io/mesh_read.h"
#include "framework/util/error.h"

namespace {

struct Image {
  int size;
  std::vector<std::uint8_t> rgb;
  std::vector<double> depth;
  explicit Image(int n) : size(n), rgb(3 * size_t(n) * n, 255), depth(size_t(n) * n, -1e300) {}
  void put(int x, int y, double z, std::array<std::uint8_t, 3> c) {
    if (x < 0 || y < 0 || x >= size || y >= size) return;
    const size_t i = size_t(y) * size + x;
    if (z < depth[i]) return;
    depth[i] = z;
    std::copy(c.begin(), c.end(), rgb.begin() + 3 * i);
  }
};

using Vec = std::array<double, 3>;

// View space: x right, y up, z towards the viewer.
std::vector<Vec> view(const std::vector<double>& p, double azimuth, double elevation) {
  const double a = azimuth * M_PI / 180, e = elevation * M_PI / 180;
  std::vector<Vec> out(p.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) {
    const double x = p[3 * i], y = p[3 * i + 1], z = p[3 * i + 2];
    const double x1 = std::cos(a) * x + std::sin(a) * z, z1 = -std::sin(a) * x + std::cos(a) * z;
    out[i] = {x1, std::cos(e) * y - std::sin(e) * z1, std::sin(e) * y + std::cos(e) * z1};
  }
  return out;
}

// The colour at barycentric weights (w0, w1, w2) of a triangle's corners.
using Shader = std::function<std::array<std::uint8_t, 3>(double, double, double)>;

void triangle(Image& img, const Vec& a, const Vec& b, const Vec& c, const Shader& colour) {
  const int x0 = std::max(0, int(std::floor(std::min({a[0], b[0], c[0]})))),
            x1 = std::min(img.size - 1, int(std::ceil(std::max({a[0], b[0], c[0]}))));
  const int y0 = std::max(0, int(std::floor(std::min({a[1], b[1], c[1]})))),
            y1 = std::min(img.size - 1, int(std::ceil(std::max({a[1], b[1], c[1]}))));
  const double area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  if (std::abs(area) < 1e-12) return;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double w0 = ((b[0] - px) * (c[1] - py) - (c[0] - px) * (b[1] - py)) / area;
      const double w1 = ((c[0] - px) * (a[1] - py) - (a[0] - px) * (c[1] - py)) / area;
      const double w2 = 1 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      img.put(x, y, w0 * a[2] + w1 * b[2] + w2 * c[2], colour(w0, w1, w2));
    }
}

void line(Image& img, const Vec& a, const Vec& b, std::array<std::uint8_t, 3> colour, int width, double bias) {
  const int steps = int(std::max(std::abs(b[0] - a[0]), std::abs(b[1] - a[1]))) + 1;
  for (int s = 0; s <= steps; ++s) {
    const double t = double(s) / steps;
    const double x = a[0] + t * (b[0] - a[0]), y = a[1] + t * (b[1] - a[1]), z = a[2] + t * (b[2] - a[2]) + bias;
    for (int dy = -width / 2; dy <= width / 2; ++dy)
      for (int dx = -width / 2; dx <= width / 2; ++dx) img.put(int(x) + dx, int(y) + dy, z, colour);
  }
}

void chunk(std::ofstream& out, const char* type, const std::vector<std::uint8_t>& data) {
  const std::uint32_t n = std::uint32_t(data.size());
  const std::uint8_t len[4] = {std::uint8_t(n >> 24), std::uint8_t(n >> 16), std::uint8_t(n >> 8), std::uint8_t(n)};
  out.write(reinterpret_cast<const char*>(len), 4);
  out.write(type, 4);
  out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
  uLong crc = crc32(0, reinterpret_cast<const Bytef*>(type), 4);
  crc = crc32(crc, data.data(), uInt(data.size()));
  const std::uint8_t c[4] = {std::uint8_t(crc >> 24), std::uint8_t(crc >> 16), std::uint8_t(crc >> 8), std::uint8_t(crc)};
  out.write(reinterpret_cast<const char*>(c), 4);
}

// PNG (RFC 2083): 8-bit RGB, no filtering, one zlib stream.
void write_png(const std::string& file, const Image& img) {
  std::vector<std::uint8_t> raw;
  for (int y = img.size - 1; y >= 0; --y) {  // image rows top first; our y points up
    raw.push_back(0);
    raw.insert(raw.end(), img.rgb.begin() + 3 * size_t(y) * img.size, img.rgb.begin() + 3 * size_t(y + 1) * img.size);
  }
  uLongf packed_size = compressBound(uLong(raw.size()));
  std::vector<std::uint8_t> packed(packed_size);
  if (compress2(packed.data(), &packed_size, raw.data(), uLong(raw.size()), 9) != Z_OK)
    throw subdiv::Error("zlib could not compress the image");
  packed.resize(packed_size);
  std::ofstream out(file, std::ios::binary);
  if (!out) throw subdiv::Error(fmt::format("cannot write '{}'", file));
  out.write("\x89PNG\r\n\x1a\n", 8);
  const std::uint32_t n = std::uint32_t(img.size);
  std::vector<std::uint8_t> header = {std::uint8_t(n >> 24), std::uint8_t(n >> 16), std::uint8_t(n >> 8), std::uint8_t(n),
                                      std::uint8_t(n >> 24), std::uint8_t(n >> 16), std::uint8_t(n >> 8), std::uint8_t(n),
                                      8, 2, 0, 0, 0};
  chunk(out, "IHDR", header);
  chunk(out, "IDAT", packed);
  chunk(out, "IEND", {});
}

// (u, v) per face corner: the first face-varying texture coordinates, else per-point ones;
// empty when the mesh has none.
std::vector<double> corner_uvs(const subdiv::MeshData& mesh) {
  std::vector<double> out;
  for (const auto& a : mesh.face_varying)
    if (a.role == subdiv::ArrayRole::TextureCoordinates && a.components >= 2) {
      for (subdiv::Index i : a.indices) out.insert(out.end(), {a.values[i * a.components], a.values[i * a.components + 1]});
      return out;
    }
  for (const auto& a : mesh.point_data)
    if (a.role == subdiv::ArrayRole::TextureCoordinates && a.components >= 2) {
      for (subdiv::Index v : mesh.face_vertices) out.insert(out.end(), {a.values[v * a.components], a.values[v * a.components + 1]});
      return out;
    }
  return out;
}

// Matplotlib's viridis (van der Walt & Smith 2015) at 0, 1/4, 1/2, 3/4, 1, linearly between.
std::array<double, 3> viridis(double t) {
  static constexpr double stops[5][3] = {
      {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::clamp(t, 0.0, 1.0) * 4;
  const int i = std::min(3, int(t));
  const double f = t - i;
  return {stops[i][0] + f * (stops[i + 1][0] - stops[i][0]), stops[i][1] + f * (stops[i + 1][1] - stops[i][1]),
          stops[i][2] + f * (stops[i + 1][2] - stops[i][2])};
}

// The scalar point array `name`; refused naming the mesh when it has none of one component.
std::vector<double> scalar_array(const subdiv::MeshData& mesh, const std::string& name, const std::string& file) {
  for (const auto& a : mesh.point_data)
    if (a.name == name && a.components == 1) return a.values;
  throw subdiv::Error(fmt::format("--color-by: '{}' has no scalar point array '{}'", file, name));
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 3) {
    std::fprintf(stderr, "usage: subdiv-render MESH OUT.png [--azimuth DEG] [--elevation DEG] [--size PIXELS] [--cage MESH] "
                         "[--checker N] [--color-by ARRAY] [--edges 0|1]\n");
    return 2;
  }
  double azimuth = 30, elevation = 25;
  int size = 640, checker = 0, edges = 1;
  std::string cage_file, color_by;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string o = argv[i];
    if (o == "--azimuth") azimuth = std::stod(argv[i + 1]);
    else if (o == "--elevation") elevation = std::stod(argv[i + 1]);
    else if (o == "--size") size = std::stoi(argv[i + 1]);
    else if (o == "--cage") cage_file = argv[i + 1];
    else if (o == "--checker") checker = std::stoi(argv[i + 1]);
    else if (o == "--color-by") color_by = argv[i + 1];
    else if (o == "--edges") edges = std::stoi(argv[i + 1]);
    else throw subdiv::Error(fmt::format("unknown option '{}'", o));
  }
  const subdiv::MeshData mesh = subdiv::read_mesh(argv[1]);
  std::vector<Vec> p = view(mesh.positions, azimuth, elevation);
  subdiv::MeshData cage;
  std::vector<Vec> q;
  if (!cage_file.empty()) cage = subdiv::read_mesh(cage_file), q = view(cage.positions, azimuth, elevation);
  // Fit the picture: the same scale and offset for the mesh and its cage.
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto* points : {&p, &q})
    for (const Vec& v : *points)
      for (int c = 0; c < 2; ++c) lo[c] = std::min(lo[c], v[c]), hi[c] = std::max(hi[c], v[c]);
  const double scale = 0.9 * size / std::max(hi[0] - lo[0], hi[1] - lo[1]);
  auto to_pixels = [&](std::vector<Vec>& points) {
    for (Vec& v : points)
      for (int c = 0; c < 3; ++c) v[c] = (c < 2 ? (v[c] - 0.5 * (lo[c] + hi[c])) * scale + 0.5 * size : v[c] * scale);
  };
  to_pixels(p), to_pixels(q);
  const std::vector<double> uv = corner_uvs(mesh);
  if (checker > 0 && uv.empty()) throw subdiv::Error(fmt::format("--checker: '{}' has no texture coordinates", argv[1]));
  std::vector<double> scalar;
  double scalar_max = 0;
  if (!color_by.empty()) {
    scalar = scalar_array(mesh, color_by, argv[1]);
    for (double x : scalar) scalar_max = std::max(scalar_max, x);
    std::printf("%s: 0 (bottom of the bar) to %.3e (top)\n", color_by.c_str(), scalar_max);
  }
  Image img(size);
  for (subdiv::Index f = 0; f < mesh.face_count(); ++f) {
    const subdiv::Index o = mesh.face_offsets[f], k = mesh.face_offsets[f + 1] - o;
    const Vec &a = p[mesh.face_vertices[o]], &b = p[mesh.face_vertices[o + 1]], &c = p[mesh.face_vertices[o + 2]];
    const Vec u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    Vec n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) + 1e-300;
    const double light = std::abs((0.3 * n[0] + 0.5 * n[1] + 0.81 * n[2]) / len);  // two-sided
    const double shade = 0.3 + 0.7 * light;
    const std::array<std::uint8_t, 3> colour{std::uint8_t(90 * shade), std::uint8_t(150 * shade), std::uint8_t(220 * shade)};
    for (subdiv::Index i = 1; i + 1 < k; ++i) {
      const subdiv::Index corners[3] = {o, o + i, o + i + 1};
      const Shader plain = [&](double, double, double) { return colour; };
      const Shader squares = [&](double w0, double w1, double w2) {
        double t[2];
        for (int d = 0; d < 2; ++d)
          t[d] = w0 * uv[2 * corners[0] + d] + w1 * uv[2 * corners[1] + d] + w2 * uv[2 * corners[2] + d];
        const bool dark = (int(std::floor(t[0] * checker)) + int(std::floor(t[1] * checker))) % 2 != 0;
        const double tone = dark ? 0.35 : 1.0;
        return std::array<std::uint8_t, 3>{std::uint8_t(240 * shade * tone), std::uint8_t(200 * shade * tone),
                                           std::uint8_t(120 * shade * tone)};
      };
      const Shader mapped = [&](double w0, double w1, double w2) {
        const double x = w0 * scalar[mesh.face_vertices[corners[0]]] + w1 * scalar[mesh.face_vertices[corners[1]]] +
                         w2 * scalar[mesh.face_vertices[corners[2]]];
        const auto c = viridis(scalar_max > 0 ? x / scalar_max : 0);
        const double lit = 0.55 + 0.45 * light;
        return std::array<std::uint8_t, 3>{std::uint8_t(c[0] * lit), std::uint8_t(c[1] * lit), std::uint8_t(c[2] * lit)};
      };
      triangle(img, p[mesh.face_vertices[corners[0]]], p[mesh.face_vertices[corners[1]]],
               p[mesh.face_vertices[corners[2]]], !scalar.empty() ? mapped : checker > 0 ? squares : plain);
    }
  }
  for (subdiv::Index f = 0; edges && f < mesh.face_count(); ++f)
    for (subdiv::Index c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c) {
      const subdiv::Index next = c + 1 == mesh.face_offsets[f + 1] ? mesh.face_offsets[f] : c + 1;
      line(img, p[mesh.face_vertices[c]], p[mesh.face_vertices[next]], {40, 60, 90}, 1, 0.5);
    }
  if (!scalar.empty())  // the colour bar: 0 at the bottom, the largest value at the top
    for (int y = size / 10; y < size - size / 10; ++y)
      for (int x = size - size / 25 - 12; x < size - size / 25; ++x) {
        const auto c = viridis(double(y - size / 10) / (size - 2 * (size / 10)));
        img.put(x, y, 1e300, {std::uint8_t(c[0]), std::uint8_t(c[1]), std::uint8_t(c[2])});
      }
  for (subdiv::Index f = 0; f < cage.face_count(); ++f)
    for (subdiv::Index c = cage.face_offsets[f]; c < cage.face_offsets[f + 1]; ++c) {
      const subdiv::Index next = c + 1 == cage.face_offsets[f + 1] ? cage.face_offsets[f] : c + 1;
      line(img, q[cage.face_vertices[c]], q[cage.face_vertices[next]], {200, 60, 40}, 3, 1e6);  // always in front
    }
  // Polylines (OBJ 'l'): a refined curve in the mesh's tone, a control polygon in the cage's.
  for (subdiv::Index l = 0; l < mesh.line_count(); ++l)
    for (subdiv::Index c = mesh.line_offsets[l]; c + 1 < mesh.line_offsets[l + 1]; ++c)
      line(img, p[mesh.line_vertices[c]], p[mesh.line_vertices[c + 1]], {30, 70, 160}, 3, 1e6);
  for (subdiv::Index l = 0; l < cage.line_count(); ++l)
    for (subdiv::Index c = cage.line_offsets[l]; c + 1 < cage.line_offsets[l + 1]; ++c)
      line(img, q[cage.line_vertices[c]], q[cage.line_vertices[c + 1]], {200, 60, 40}, 2, 1e6);
  write_png(argv[2], img);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "subdiv-render: error: %s\n", e.what());
  return 1;
}
