#include "framework/io/vtk/vtp_fast_read.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <utility>
#include <memory>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/io/vtk/vtk_read.h"
#include "framework/io/vtk/vtp_array_decode.h"
#include "framework/io/vtk/vtp_layout.h"
#include "framework/io/vtk/vtp_sinks.h"
#include "framework/util/memory_limit.h"

namespace subdiv::io_detail {
namespace {

struct Decline {};

void require(bool ok) {
  if (!ok) throw Decline{};
}

// Runs body(begin, end) over [0, n) on every core, in pieces of at least `grain`.
template <class Body>
void parallel(std::size_t n, Body body, std::size_t grain = 1 << 16) {
  if (n <= grain) return body(std::size_t(0), n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
}

class FastReader {
public:
  FastReader(std::string_view bytes, VtpLayout layout) : bytes_(bytes), l_(std::move(layout)) {}

  MeshData run() {
    require(l_.strips == 0 && l_.coordinates);
    const double cells = double(l_.verts) + double(l_.lines) + double(l_.polys);
    // What VTK's reader and the conversion would hold (as vtk_xml_check.cpp counts it).
    budget_ = available_memory().bytes;
    require(double(l_.points) * 48 + cells * 80 <= budget_);
    for (int k = 0; k < 4; ++k) require(l_.cells[k].present || count_of(k) == 0);
    for (const VtpArray& a : l_.field) discard(a, std::size_t(a.tuples));
    MeshData mesh;
    positions(mesh);
    std::vector<std::int64_t> offsets[3];
    DecodedBytes connectivity[3];
    for (int k = 0; k < 3; ++k)
      if (l_.cells[k].present) cell_arrays(k, offsets[k], connectivity[k]);
    if (l_.cells[3].present) faces(mesh);
    lines(mesh, offsets[1], connectivity[1]);
    const std::size_t all_cells = std::size_t(l_.verts + l_.lines + l_.polys);
    point_arrays(mesh);
    user_arrays(mesh.cell_data, l_.cell_data, false, all_cells, std::size_t(l_.verts + l_.lines),
                std::size_t(l_.polys));
    return mesh;
  }

private:
  long long count_of(int kind) const {
    const long long counts[4] = {l_.verts, l_.lines, l_.strips, l_.polys};
    return counts[kind];
  }

  std::size_t bytes_of(const VtpArray& a, std::size_t tuples) const {
    return tuples * std::size_t(a.components) * vtp_type_size(a.type);
  }

  DecodedBytes decode(const VtpArray& a, std::size_t tuples) {
    auto out = decode_vtp_array(bytes_, a, bytes_of(a, tuples), l_.header_bytes, l_.compressor);
    require(bool(out));
    return std::move(*out);
  }

  void into(const VtpArray& a, std::size_t tuples, ArraySink& sink) {
    require(decode_vtp_array_into(bytes_, a, bytes_of(a, tuples), l_.header_bytes, l_.compressor, sink));
  }

  void discard(const VtpArray& a, std::size_t tuples) {
    DiscardSink sink;
    into(a, tuples, sink);
  }

  void positions(MeshData& mesh) {
    const VtpArray& a = *l_.coordinates;
    mesh.positions.resize(std::size_t(l_.points) * 3);
    ConvertSink<double> sink(a.type, a.type == VtpType::Float64, mesh.positions.data());
    into(a, std::size_t(l_.points), sink);
  }

  // Offsets (each cell's end) strictly increasing from at least 1 to the connectivity's size:
  // every cell has a point. VTK's reader takes other forms too; those go to it.
  void cell_arrays(int kind, std::vector<std::int64_t>& offsets, DecodedBytes& connectivity) {
    const VtpCells& c = l_.cells[kind];
    const std::size_t n = std::size_t(count_of(kind));
    offsets.resize(n + 1);
    offsets[0] = 0;
    ConvertSink<std::int64_t> sink(c.offsets.type, c.offsets.type == VtpType::Int64, offsets.data() + 1);
    sink.check(1, std::numeric_limits<std::int64_t>::max());
    into(c.offsets, n, sink);
    require(sink.good() && increasing(offsets.data(), n));
    const std::uint64_t total = std::uint64_t(offsets[n]);
    require(double(total) * 8 <= budget_);
    connectivity = decode(c.connectivity, std::size_t(total));
    connectivity_type_[kind] = c.connectivity.type;
  }

  // values[0..n] strictly increasing, values[1] >= 1 checked by the caller's sink or here.
  template <class T>
  static bool increasing(const T* values, std::size_t n) {
    std::atomic<bool> ok{true};
    parallel(n, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i)
        if (values[i + 1] <= values[i]) ok = false;
    });
    return ok;
  }

  // Polygons straight into the mesh's arrays (Int32 files need no conversion).
  void faces(MeshData& mesh) {
    const VtpCells& c = l_.cells[3];
    const std::size_t n = std::size_t(l_.polys);
    mesh.face_offsets.resize(n + 1);
    mesh.face_offsets[0] = 0;
    ConvertSink<Index> offsets(c.offsets.type, c.offsets.type == VtpType::Int32, mesh.face_offsets.data() + 1);
    offsets.check(1, std::numeric_limits<Index>::max());
    into(c.offsets, n, offsets);
    require(offsets.good() && increasing(mesh.face_offsets.data(), n));
    const std::size_t total = std::size_t(mesh.face_offsets[n]);
    mesh.face_vertices.resize(total);
    ConvertSink<Index> ids(c.connectivity.type, c.connectivity.type == VtpType::Int32, mesh.face_vertices.data());
    ids.check(0, l_.points - 1);
    into(c.connectivity, total, ids);
    require(ids.good());
  }

  // Ids of `kind` cells as Index, each checked against the points.
  void ids(int kind, const DecodedBytes& data, std::size_t count, Index* out) {
    std::atomic<bool> ok{true};
    const auto points = std::uint64_t(l_.points);
    with_type(connectivity_type_[kind], [&](auto tag) {
      using T = decltype(tag);
      parallel(count, [&](std::size_t b, std::size_t e) {
        bool good = true;
        for (std::size_t i = b; i < e; ++i) {
          const T v = load<T>(data.bytes, i);
          if constexpr (std::is_signed_v<T>) good = good && v >= T(0);
          good = good && std::uint64_t(v) < points;
          out[i] = Index(v);
        }
        if (!good) ok = false;
      });
    });
    require(ok);
  }

  const VtpArray* named(const VtpSection& section, std::string_view name) const {
    for (const VtpArray& a : section.arrays)
      if (a.name == name) return &a;
    return nullptr;
  }

  static double value(const VtpArray& a, const DecodedBytes& data, std::size_t i) {
    double v = 0;
    with_type(a.type, [&](auto tag) { v = static_cast<double>(load<decltype(tag)>(data.bytes, i)); });
    return v;
  }

  // Line cells: polylines, or crease edges where write_vtp's cell_kind says 2 (as
  // polydata_to_mesh_data reads them).
  void lines(MeshData& mesh, const std::vector<std::int64_t>& offsets, const DecodedBytes& connectivity) {
    if (l_.lines == 0) return;
    const std::size_t total = std::size_t(offsets.back());
    std::vector<Index> all(total);
    ids(1, connectivity, total, all.data());
    const VtpArray* kind_array = named(l_.cell_data, "cell_kind");
    const VtpArray* sharp_array = named(l_.cell_data, "sharpness");
    const bool tagged = kind_array && sharp_array;
    DecodedBytes kind, sharpness;
    const std::size_t cells = std::size_t(l_.verts + l_.lines + l_.polys);
    if (tagged) {
      require(kind_array->components == 1 && sharp_array->components == 1);
      kind = decode(*kind_array, cells);
      sharpness = decode(*sharp_array, cells);
    }
    for (std::size_t c = 0; c < std::size_t(l_.lines); ++c) {
      const std::size_t begin = std::size_t(offsets[c]), size = std::size_t(offsets[c + 1]) - begin;
      const std::size_t cell = std::size_t(l_.verts) + c;
      if (tagged && size == 2 && value(*kind_array, kind, cell) == 2) {
        mesh.creases.push_back({all[begin], all[begin + 1], value(*sharp_array, sharpness, cell)});
        continue;
      }
      mesh.line_vertices.insert(mesh.line_vertices.end(), all.begin() + std::ptrdiff_t(begin),
                                all.begin() + std::ptrdiff_t(begin + size));
      mesh.line_offsets.push_back(Index(mesh.line_vertices.size()));
    }
  }

  void point_arrays(MeshData& mesh) {
    if (const VtpArray* corners = named(l_.point_data, "corner_sharpness"); corners && l_.points > 0) {
      require(corners->components == 1);
      NonzeroSink sink(corners->type);
      into(*corners, std::size_t(l_.points), sink);
      mesh.corners = sink.take();
    }
    user_arrays(mesh.point_data, l_.point_data, true, std::size_t(l_.points), 0, std::size_t(l_.points));
  }

  // The role VTK's active attributes give (vtkDataSetAttributes::SetActiveAttribute takes an
  // array only with the attribute's component count: normals 3, texture coordinates 1 to 3,
  // scalars 1 to 4), as read_arrays in vtk_read.cpp reads it.
  static ArrayRole role(const VtpSection& s, const VtpArray& a) {
    if (!s.normals.empty() && a.name == s.normals && a.components == 3) return ArrayRole::Normals;
    if (!s.tcoords.empty() && a.name == s.tcoords && a.components <= 3) return ArrayRole::TextureCoordinates;
    if (!s.scalars.empty() && a.name == s.scalars && a.components <= 4 && a.type == VtpType::UInt8)
      return ArrayRole::Color;
    return ArrayRole::Data;
  }

  // The user's arrays of a section holding `tuples` tuples, those [first, first + count) kept
  // (cell data: the polygons'); SubdivKit's own arrays decoded and checked only (corner_sharpness
  // was read already; cell_kind and sharpness by lines()).
  void user_arrays(std::vector<DataArray>& out, const VtpSection& section, bool point, std::size_t tuples,
                   std::size_t first, std::size_t count) {
    for (std::size_t i = 0; i < section.arrays.size(); ++i) {
      const VtpArray& a = section.arrays[i];
      if (subdivkit_array(a.name.c_str(), point)) {
        const bool done = (point && a.name == "corner_sharpness" && l_.points > 0) ||
                          (!point && l_.lines > 0 && (a.name == "cell_kind" || a.name == "sharpness") &&
                           named(section, "cell_kind") && named(section, "sharpness"));
        if (!done) discard(a, tuples);
        continue;
      }
      DataArray d;
      d.name = a.name;
      d.components = a.components;
      d.role = role(section, a);
      const std::size_t k = std::size_t(a.components);
      if (first == 0 && count == tuples) {
        d.values.resize(count * k);
        ConvertSink<double> sink(a.type, a.type == VtpType::Float64, d.values.data());
        into(a, tuples, sink);
      } else {
        const DecodedBytes data = decode(a, tuples);
        d.values.resize(count * k);
        double* values = d.values.data();
        with_type(a.type, [&](auto tag) {
          using T = decltype(tag);
          parallel(count * k, [&](std::size_t b, std::size_t e) {
            for (std::size_t j = b; j < e; ++j) values[j] = static_cast<double>(load<T>(data.bytes, first * k + j));
          });
        });
      }
      // 64-bit ids beyond an int are carried as doubles rather than refused.
      std::atomic<bool> whole{!vtp_type_is_float(a.type)};
      if (whole) {
        const double* values = d.values.data();
        parallel(d.values.size(), [&](std::size_t b, std::size_t e) {
          bool fits = true;
          for (std::size_t j = b; j < e; ++j) fits = fits && std::abs(values[j]) <= 2147483647.0;
          if (!fits) whole = false;
        });
      }
      d.integer = whole;
      out.push_back(std::move(d));
    }
  }

  std::string_view bytes_;
  VtpLayout l_;
  VtpType connectivity_type_[4] = {};
  double budget_ = 0;
};

}  // namespace

std::optional<MeshData> read_vtp_fast_file(const std::filesystem::path& file) {
  // Mapped, not copied: raw appended data is decompressed or copied from the page cache
  // straight into the mesh, and no buffer of the file's size is touched first.
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  void* map = MAP_FAILED;
  std::size_t size = 0;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    size = std::size_t(st.st_size);
    map = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
  }
  ::close(fd);
  if (map == MAP_FAILED) return std::nullopt;
  std::optional<MeshData> mesh = read_vtp_fast(std::string_view(static_cast<const char*>(map), size));
  ::munmap(map, size);
  return mesh;
}

std::optional<MeshData> read_vtp_fast(std::string_view bytes) {
  std::optional<VtpLayout> layout = parse_vtp_layout(bytes);
  if (!layout) return std::nullopt;
  try {
    return FastReader(bytes, std::move(*layout)).run();
  } catch (const Decline&) {
    return std::nullopt;
  }
}

}  // namespace subdiv::io_detail
