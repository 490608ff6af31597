#include "framework/io/om_check.h"

#include <cstdint>
#include <fmt/format.h>
#include <string>
#include <vector>

#include <OpenMesh/Core/IO/OMFormat.hh>
#include <OpenMesh/Core/IO/writer/OMWriter.hh>

#include "framework/io/text_input.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;
namespace om = OpenMesh::IO::OMFormat;

namespace {

constexpr std::size_t kHeaderBytes = 16;  // "OM", mesh kind, version, three uint32 counts

class OmChecker {
public:
  OmChecker(const fs::path& file, std::string_view bytes) : file_(file), bytes_(bytes) {}

  void run() {
    header();
    while (pos_ + 2 <= bytes_.size()) {  // the reader stops where no chunk header fits
      const std::size_t chunk_at = pos_;
      om::Chunk::Header chunk;
      chunk << std::uint16_t(unsigned_at(pos_, 2));
      pos_ += 2;
      if (chunk.entity_ == om::Chunk::Entity_Sentinel) break;
      if (chunk.name_ || chunk.type_ == om::Chunk::Type_Custom)
        fail(chunk_at, "the file has custom properties; SubdivKit reads positions and topology only: save the "
                       "mesh without custom properties");
      switch (chunk.entity_) {
        case om::Chunk::Entity_Vertex: vertex_chunk(chunk, chunk_at); break;
        case om::Chunk::Entity_Face: face_chunk(chunk, chunk_at); break;
        case om::Chunk::Entity_Edge: unsupported(chunk, chunk_at);
        case om::Chunk::Entity_Halfedge: halfedge_chunk(chunk, chunk_at); break;
        case om::Chunk::Entity_Mesh: unsupported(chunk, chunk_at);
        default: fail(chunk_at, fmt::format("unknown chunk entity {}; the file is damaged", unsigned(chunk.entity_)));
      }
    }
    topology();
  }

private:
  [[noreturn]] void fail(std::size_t at, const std::string& problem) const {
    throw Error(fmt::format("{}: byte {}: {}", escaped(file_.string()), at, problem));
  }

  std::uint64_t unsigned_at(std::size_t at, std::size_t size) const {  // little-endian
    std::uint64_t v = 0;
    for (std::size_t i = size; i-- > 0;) v = (v << 8) | static_cast<unsigned char>(bytes_[at + i]);
    return v;
  }

  void header() {
    if (bytes_.size() < kHeaderBytes) fail(0, "the file is shorter than an .om header; it is cut off");
    if (bytes_[0] != 'O' || bytes_[1] != 'M') fail(0, "not an OpenMesh file: it must start with \"OM\"");
    if (bytes_[2] != 'T' && bytes_[2] != 'Q' && bytes_[2] != 'P')
      fail(2, "unknown mesh kind; an .om file is a T(riangle), Q(uad) or P(olygon) mesh");
    const auto version = static_cast<om::uint8>(bytes_[3]);
    if (om::major_version(version) < 2 || version > OpenMesh::IO::_OMWriter_::get_version())
      fail(3, fmt::format(".om version {} is not one this OpenMesh reads safely (2.0 up to {})",
                          om::as_string(version), om::as_string(OpenMesh::IO::_OMWriter_::get_version())));
    vertices_ = unsigned_at(4, 4), faces_ = unsigned_at(8, 4), edges_ = unsigned_at(12, 4);
    // Every element needs at least one byte of the file.
    for (const auto& [count, what] : {std::pair{vertices_, "vertices"}, {faces_, "faces"}, {edges_, "edges"}})
      if (count > bytes_.size())
        fail(4, fmt::format("the header says {} {}, more than the file's {} bytes can hold", count, what,
                            bytes_.size()));
    pos_ = kHeaderBytes;
  }

  // Skips `count` elements of `size` bytes each after checking that they are in the file.
  void skip(std::uint64_t count, std::uint64_t size, std::size_t chunk_at) {
    if (size != 0 && count > (bytes_.size() - pos_) / size)
      fail(chunk_at, fmt::format("the chunk needs {} bytes, but only {} follow; the file is cut off", count * size,
                                 bytes_.size() - pos_));
    pos_ += count * size;
  }

  // Ids as the reader reads them: integers of the chunk's width, kept as int.
  std::vector<std::int64_t> ids(std::uint64_t count, const om::Chunk::Header& chunk, std::size_t chunk_at) {
    const std::size_t width = std::size_t(1) << chunk.bits_;  // Integer_8 .. Integer_64
    const std::size_t start = pos_;
    skip(count, width, chunk_at);
    std::vector<std::int64_t> out(count);
    for (std::uint64_t i = 0; i < count; ++i) {
      std::uint64_t v = unsigned_at(start + i * width, width);
      if (width < 8 && (v >> (8 * width - 1)) != 0) v |= ~std::uint64_t(0) << (8 * width);  // sign-extend
      out[i] = std::int32_t(std::int64_t(v));  // the reader stores an int
    }
    return out;
  }

  void require_dim(const om::Chunk::Header& chunk, std::size_t dim, std::size_t chunk_at) const {
    if (om::dimensions(chunk) != dim)
      fail(chunk_at, fmt::format("a chunk of type {} has {} components instead of {}; the file is damaged",
                                 unsigned(chunk.type_), om::dimensions(chunk), dim));
  }

  // The bytes per position the reader reads: three floats of the chunk's width.
  static std::size_t position_size(const om::Chunk::Header& chunk) {
    return 3 * (chunk.bits_ == om::Chunk::Float_64 ? 8 : 4);
  }

  // Positions are 32- or 64-bit floats.
  void require_float(const om::Chunk::Header& chunk, std::size_t at) const {
    if (!chunk.float_ || (chunk.bits_ != om::Chunk::Float_32 && chunk.bits_ != om::Chunk::Float_64))
      fail(at, "positions must be 32- or 64-bit floats; the file is damaged");
  }

  // Which properties OpenMesh 9's reader reads how (double or float normals, colours of
  // three or four bytes, ...) is not documented, and a wrong guess put this walk out of
  // step with the reader (found by fuzz_read_om). SubdivKit needs positions and
  // connectivity only, so every other kind of chunk is refused rather than guessed.
  [[noreturn]] void unsupported(const om::Chunk::Header& chunk, std::size_t at) const {
    fail(at, fmt::format("the file stores more than positions and connectivity (chunk entity {}, type {}: normals, "
                         "colours, texture coordinates, status or custom data); SubdivKit reads .om files with "
                         "positions and connectivity only: save the mesh without the other properties",
                         unsigned(chunk.entity_), unsigned(chunk.type_)));
  }

  void vertex_chunk(const om::Chunk::Header& chunk, std::size_t at) {
    if (chunk.type_ == om::Chunk::Type_Pos) {
      require_dim(chunk, 3, at);
      require_float(chunk, at);
      if (has_positions_) fail(at, "a second chunk of vertex positions");
      has_positions_ = true;
      return skip(vertices_, position_size(chunk), at);
    }
    if (chunk.type_ != om::Chunk::Type_Topology) unsupported(chunk, at);
    // The reader sets each vertex's halfedge on the vertices the positions chunk created;
    // before it there are none, and OpenMesh wrote through a null pointer (found by
    // fuzz_read_om).
    if (!has_positions_)
      fail(at, "the vertex topology chunk comes before the vertex positions, so it refers to vertices that do not "
               "exist yet; the file is damaged (OpenMesh writes positions first)");
    if (!vertex_halfedges_.empty()) fail(at, "a second chunk of vertex topology");
    vertex_halfedges_ = ids(vertices_, chunk, at);
  }

  void face_chunk(const om::Chunk::Header& chunk, std::size_t at) {
    if (chunk.type_ != om::Chunk::Type_Topology) unsupported(chunk, at);
    if (has_faces_) fail(at, "a second chunk of face topology");
    has_faces_ = true;
    face_halfedges_ = ids(faces_, chunk, at);
  }

  void halfedge_chunk(const om::Chunk::Header& chunk, std::size_t at) {
    if (chunk.type_ != om::Chunk::Type_Topology) unsupported(chunk, at);
    if (has_halfedges_) fail(at, "a second chunk of halfedge topology");
    has_halfedges_ = true;
    halfedge_ids_ = ids(6 * edges_, chunk, at);  // per edge: next, to-vertex, face for both halves
  }

  // The mesh OpenMesh would build must be one whose loops can be walked.
  void topology() const {
    const std::int64_t vertices = has_positions_ ? std::int64_t(vertices_) : 0;
    const std::int64_t halfedges = has_halfedges_ ? 2 * std::int64_t(edges_) : 0;
    const std::int64_t faces = has_faces_ ? std::int64_t(faces_) : 0;
    const std::size_t end = bytes_.size();
    std::vector<std::int64_t> next(halfedges);
    for (std::int64_t h = 0; h < halfedges; ++h) {
      const std::int64_t* ids = &halfedge_ids_[3 * h];  // next, to-vertex, face
      if (ids[0] < 0 || ids[0] >= halfedges || ids[1] < 0 || ids[1] >= vertices || ids[2] < -1 || ids[2] >= faces)
        fail(end, fmt::format("halfedge {} refers to halfedge {}, vertex {} or face {}, beyond the {} halfedges, {} "
                              "vertices and {} faces the file has; the file is damaged",
                              h, ids[0], ids[1], ids[2], halfedges, vertices, faces));
      next[h] = ids[0];
    }
    for (std::size_t v = 0; v < vertex_halfedges_.size(); ++v)
      if (vertex_halfedges_[v] < -1 || vertex_halfedges_[v] >= halfedges)
        fail(end, fmt::format("vertex {} refers to halfedge {}, but the file has {}", v, vertex_halfedges_[v],
                              halfedges));
    for (std::size_t f = 0; f < face_halfedges_.size(); ++f) {
      const std::int64_t start = face_halfedges_[f];
      if (start < 0 || start >= halfedges)
        fail(end, fmt::format("face {} refers to halfedge {}, but the file has {}", f, start, halfedges));
      std::int64_t h = start, steps = 0;
      do {
        h = next[h];
        if (++steps > halfedges)
          fail(end, fmt::format("the halfedge loop of face {} never comes back to its start; the file is damaged", f));
      } while (h != start);
    }
  }

  const fs::path& file_;
  std::string_view bytes_;
  std::size_t pos_ = 0;
  std::uint64_t vertices_ = 0, faces_ = 0, edges_ = 0;
  bool has_positions_ = false, has_faces_ = false, has_halfedges_ = false;
  std::vector<std::int64_t> vertex_halfedges_, face_halfedges_, halfedge_ids_;
};

}  // namespace

void check_om_bytes(const fs::path& file, std::string_view bytes) { OmChecker(file, bytes).run(); }

void check_om_file(const fs::path& file) { check_om_bytes(file, read_whole_file(file)); }

}  // namespace subdiv::io_detail
