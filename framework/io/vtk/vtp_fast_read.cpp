#include "framework/io/vtk/vtp_fast_read.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
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
#include "framework/util/memory_limit.h"

namespace subdiv::io_detail {
namespace {

struct Decline {};

void require(bool ok) {
  if (!ok) throw Decline{};
}

// Calls f(T{}) with the C++ type of `type`.
template <class F>
void with_type(VtpType type, F&& f) {
  switch (type) {
    case VtpType::Int8: return f(std::int8_t{});
    case VtpType::UInt8: return f(std::uint8_t{});
    case VtpType::Int16: return f(std::int16_t{});
    case VtpType::UInt16: return f(std::uint16_t{});
    case VtpType::Int32: return f(std::int32_t{});
    case VtpType::UInt32: return f(std::uint32_t{});
    case VtpType::Int64: return f(std::int64_t{});
    case VtpType::UInt64: return f(std::uint64_t{});
    case VtpType::Float32: return f(float{});
    case VtpType::Float64: return f(double{});
  }
}

// Values may lie anywhere in the file (raw appended data): loaded with memcpy.
template <class T>
T load(const unsigned char* bytes, std::size_t i) {
  T v;
  std::memcpy(&v, bytes + i * sizeof(T), sizeof(T));
  return v;
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
    for (const VtpArray& a : l_.field) decode(a, std::size_t(a.tuples));
    MeshData mesh;
    positions(mesh);
    std::vector<std::int64_t> offsets[4];
    DecodedBytes connectivity[4];
    for (int k = 0; k < 4; ++k)
      if (l_.cells[k].present) cell_arrays(k, offsets[k], connectivity[k]);
    faces(mesh, offsets[3], connectivity[3]);
    std::vector<DecodedBytes> point_arrays, cell_arrays_;
    for (const VtpArray& a : l_.point_data.arrays) point_arrays.push_back(decode(a, std::size_t(l_.points)));
    const std::size_t all_cells = std::size_t(l_.verts + l_.lines + l_.polys);
    for (const VtpArray& a : l_.cell_data.arrays) cell_arrays_.push_back(decode(a, all_cells));
    lines(mesh, offsets[1], connectivity[1], cell_arrays_);
    corners(mesh, point_arrays);
    user_arrays(mesh.point_data, l_.point_data, point_arrays, true, 0, std::size_t(l_.points));
    user_arrays(mesh.cell_data, l_.cell_data, cell_arrays_, false, std::size_t(l_.verts + l_.lines),
                std::size_t(l_.polys));
    return mesh;
  }

private:
  long long count_of(int kind) const {
    const long long counts[4] = {l_.verts, l_.lines, l_.strips, l_.polys};
    return counts[kind];
  }

  DecodedBytes decode(const VtpArray& a, std::size_t tuples) {
    const std::size_t bytes = tuples * std::size_t(a.components) * vtp_type_size(a.type);
    auto out = decode_vtp_array(bytes_, a, bytes, l_.header_bytes, l_.compressor);
    require(bool(out));
    return std::move(*out);
  }

  void positions(MeshData& mesh) {
    const VtpArray& a = *l_.coordinates;
    const DecodedBytes data = decode(a, std::size_t(l_.points));
    const std::size_t n = std::size_t(l_.points) * 3;
    mesh.positions.resize(n);
    double* out = mesh.positions.data();
    if (a.type == VtpType::Float64) {
      parallel(n, [&](std::size_t b, std::size_t e) { std::memcpy(out + b, data.bytes + b * 8, (e - b) * 8); }, 1 << 18);
      return;
    }
    with_type(a.type, [&](auto tag) {
      using T = decltype(tag);
      parallel(n, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) out[i] = static_cast<double>(load<T>(data.bytes, i));
      });
    });
  }

  // Offsets (each cell's end) strictly increasing from at least 1 to the connectivity's size:
  // every cell has a point. VTK's reader takes other forms too; those go to it.
  void cell_arrays(int kind, std::vector<std::int64_t>& offsets, DecodedBytes& connectivity) {
    const VtpCells& c = l_.cells[kind];
    const std::size_t n = std::size_t(count_of(kind));
    const DecodedBytes raw = decode(c.offsets, n);
    offsets.resize(n + 1);
    offsets[0] = 0;
    std::atomic<bool> ok{true};
    with_type(c.offsets.type, [&](auto tag) {
      using T = decltype(tag);
      parallel(n, [&](std::size_t b, std::size_t e) {
        bool good = true;
        for (std::size_t i = b; i < e; ++i) {
          const T v = load<T>(raw.bytes, i);
          good = good && v >= T(1) && std::uint64_t(v) <= std::uint64_t(std::numeric_limits<std::int64_t>::max());
          offsets[i + 1] = std::int64_t(v);
        }
        if (!good) ok = false;
      });
    });
    require(ok);
    parallel(n, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i)
        if (offsets[i + 1] <= offsets[i]) ok = false;
    });
    require(ok);
    const std::uint64_t total = std::uint64_t(offsets[n]);
    require(double(total) * 8 <= budget_);
    connectivity = decode(c.connectivity, std::size_t(total));
    connectivity_type_[kind] = c.connectivity.type;
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

  void faces(MeshData& mesh, const std::vector<std::int64_t>& offsets, const DecodedBytes& connectivity) {
    if (!l_.cells[3].present) return;
    const std::size_t n = std::size_t(l_.polys), total = std::size_t(offsets[n]);
    mesh.face_vertices.resize(total);
    ids(3, connectivity, total, mesh.face_vertices.data());
    mesh.face_offsets.resize(n + 1);
    Index* out = mesh.face_offsets.data();
    parallel(n + 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) out[i] = Index(offsets[i]);
    });
  }

  static const DecodedBytes* named(const VtpSection& section, const std::vector<DecodedBytes>& data,
                                   std::string_view name, const VtpArray** array) {
    for (std::size_t i = 0; i < section.arrays.size(); ++i)
      if (section.arrays[i].name == name) return *array = &section.arrays[i], &data[i];
    return nullptr;
  }

  static double value(const VtpArray& a, const DecodedBytes& data, std::size_t i) {
    double v = 0;
    with_type(a.type, [&](auto tag) { v = static_cast<double>(load<decltype(tag)>(data.bytes, i)); });
    return v;
  }

  // Line cells: polylines, or crease edges where write_vtp's cell_kind says 2 (as
  // polydata_to_mesh_data reads them).
  void lines(MeshData& mesh, const std::vector<std::int64_t>& offsets, const DecodedBytes& connectivity,
             const std::vector<DecodedBytes>& cell_data) {
    if (l_.lines == 0) return;
    const std::size_t total = std::size_t(offsets.back());
    std::vector<Index> all(total);
    ids(1, connectivity, total, all.data());
    const VtpArray *kind_array = nullptr, *sharp_array = nullptr;
    const DecodedBytes* kind = named(l_.cell_data, cell_data, "cell_kind", &kind_array);
    const DecodedBytes* sharpness = named(l_.cell_data, cell_data, "sharpness", &sharp_array);
    const bool tagged = kind && sharpness;
    if (tagged) require(kind_array->components == 1 && sharp_array->components == 1);
    for (std::size_t c = 0; c < std::size_t(l_.lines); ++c) {
      const std::size_t begin = std::size_t(offsets[c]), size = std::size_t(offsets[c + 1]) - begin;
      const std::size_t cell = std::size_t(l_.verts) + c;
      if (tagged && size == 2 && value(*kind_array, *kind, cell) == 2) {
        mesh.creases.push_back({all[begin], all[begin + 1], value(*sharp_array, *sharpness, cell)});
        continue;
      }
      mesh.line_vertices.insert(mesh.line_vertices.end(), all.begin() + std::ptrdiff_t(begin),
                                all.begin() + std::ptrdiff_t(begin + size));
      mesh.line_offsets.push_back(Index(mesh.line_vertices.size()));
    }
  }

  void corners(MeshData& mesh, const std::vector<DecodedBytes>& point_data) {
    const VtpArray* array = nullptr;
    const DecodedBytes* data = named(l_.point_data, point_data, "corner_sharpness", &array);
    if (!data || l_.points == 0) return;
    require(array->components == 1);
    for (std::size_t v = 0; v < std::size_t(l_.points); ++v)
      if (const double s = value(*array, *data, v); s != 0) mesh.corners.push_back({Index(v), s});
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

  void user_arrays(std::vector<DataArray>& out, const VtpSection& section, const std::vector<DecodedBytes>& data,
                   bool point, std::size_t first, std::size_t count) {
    for (std::size_t i = 0; i < section.arrays.size(); ++i) {
      const VtpArray& a = section.arrays[i];
      if (subdivkit_array(a.name.c_str(), point)) continue;
      DataArray d;
      d.name = a.name.empty() ? "array_" + std::to_string(i) : a.name;
      d.components = a.components;
      d.integer = !vtp_type_is_float(a.type);
      d.role = role(section, a);
      const std::size_t k = std::size_t(a.components);
      d.values.resize(count * k);
      double* values = d.values.data();
      std::atomic<bool> whole{true};
      with_type(a.type, [&](auto tag) {
        using T = decltype(tag);
        parallel(count * k, [&](std::size_t b, std::size_t e) {
          bool fits = true;
          for (std::size_t j = b; j < e; ++j) {
            values[j] = static_cast<double>(load<T>(data[i].bytes, first * k + j));
            fits = fits && std::abs(values[j]) <= 2147483647.0;
          }
          if (!fits) whole = false;
        });
      });
      // 64-bit ids beyond an int are carried as doubles rather than refused.
      d.integer = d.integer && whole;
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
  // Read whole into memory that is not zero-filled first (a std::string would be).
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  std::unique_ptr<char[]> data;
  std::size_t size = 0;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && double(st.st_size) < available_memory().bytes) {
    size = std::size_t(st.st_size);
    data.reset(new char[size]);
    std::size_t done = 0;
    while (done < size) {
      const ssize_t got = ::read(fd, data.get() + done, size - done);
      if (got <= 0) break;
      done += std::size_t(got);
    }
    if (done != size) data.reset();
  }
  ::close(fd);
  if (!data) return std::nullopt;
  return read_vtp_fast(std::string_view(data.get(), size));
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
