#include "framework/io/obj_fast_parse.h"

#include "framework/util/decimal_number.h"
#include "framework/io/io_progress.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace subdiv::io_detail {
namespace {

constexpr long long kIndexMax = std::numeric_limits<Index>::max();

// Separators between tokens, as Tokens (text_input.cpp) has them, less '\r': a '\r' that is
// not right before a '\n' ends a line for the line-by-line reader, so its line numbers and
// statements differ from ours; the fast path declines there instead.
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }
// Where a token ends: a blank, a comment, or the line's end.
bool ends_token(const char* p, const char* end) { return p == end || is_blank(*p) || *p == '#'; }

// vt (slot 0) and vn (slot 1) of one chunk.
struct Slot {
  std::vector<double> values;
  Index count = 0;     // lines (tuples)
  int components = 0;  // numbers on the chunk's first line
  std::vector<Index> corners;            // per face corner (if any gives one): 0-based, or chunk-local if relative
  std::vector<std::size_t> relative;     // corners holding a chunk-local relative number
  bool with = false, without = false;    // some corner gives a number / some does not
  long long largest = -1;                // the largest absolute (positive) number, 0-based
};

struct Chunk {
  std::vector<double> positions;
  Index vertices = 0;
  std::vector<Index> face_ends;       // chunk-local corner count after each face
  std::vector<Index> face_vertices;   // 0-based, or chunk-local for relative references
  std::vector<std::size_t> relative;  // positions in face_vertices of relative references
  long long largest = -1;             // the largest absolute vertex reference, 0-based
  Slot slots[2];
};

class ChunkParser {
public:
  explicit ChunkParser(Chunk& chunk) : c_(chunk) {}

  // False: the text holds something only the line-by-line reader handles.
  bool parse(const char* p, const char* end) {
    while (p < end) {
      const char* eol = static_cast<const char*>(std::memchr(p, '\n', std::size_t(end - p)));
      if (!eol) eol = end;
      const char* line_end = eol > p && eol[-1] == '\r' ? eol - 1 : eol;
      if (!line(p, line_end)) return false;
      p = eol == end ? end : eol + 1;
    }
    return true;
  }

private:
  bool line(const char* p, const char* end) {
    const char* start = p;
    while (p < end && is_blank(*p)) ++p;
    const char* word = p;
    while (!ends_token(p, end) && *p != '\r') ++p;
    const std::string_view keyword(word, std::size_t(p - word));
    if (keyword == "v") return vertex(p, end);
    if (keyword == "f") return face(p, end);
    if (keyword == "vt") return attribute(p, end, c_.slots[0]);
    if (keyword == "vn") return attribute(p, end, c_.slots[1]);
    if (keyword == "l" || keyword == "t") return false;
    if (!keyword.empty() && keyword[0] != '#' && !obj_spec_statement(keyword)) return false;  // warned about there
    return ignored(start, end);
  }

  // A comment, an empty line or a statement every OBJ reader skips: fine unless it hides a
  // lone '\r' or continues on the next line ('\' before any comment).
  static bool ignored(const char* start, const char* end) {
    if (std::memchr(start, '\r', std::size_t(end - start))) return false;
    const char* hash = static_cast<const char*>(std::memchr(start, '#', std::size_t(end - start)));
    const char* last = hash ? hash : end;
    while (last > start && is_blank(last[-1])) --last;
    return last == start || last[-1] != '\\';
  }

  // Moves to the next token; false at the statement's end (the line's or a comment's). A
  // lone '\r', also inside the comment, ends the line for the line-by-line reader: declined.
  static bool next_token(const char*& p, const char* end, bool& declined) {
    while (p < end && is_blank(*p)) ++p;
    if (p < end && *p == '\r') declined = true;
    if (p < end && *p == '#' && std::memchr(p, '\r', std::size_t(end - p))) declined = true;
    return p < end && *p != '#' && !declined;
  }

  // parse_double's rules (text_input.cpp, decimal_number.h): its leading '+', the whole token
  // a number. Out-of-range values, which that reader turns into infinities or zeros, decline.
  static bool number(const char*& p, const char* end, double& value) {
    const char* q = p + leading_plus(std::string_view(p, std::size_t(end - p)));
    const auto [ptr, ec] = std::from_chars(q, end, value);
    if (ec != std::errc() || !ends_token(ptr, end)) return false;
    p = ptr;
    return true;
  }

  // parse_integer's rules; the integer must end at `stop` ('/' for a vertex number's head) or the token's end.
  static bool integer(const char*& p, const char* end, long long& value) {
    const char* q = p < end && *p == '+' ? p + 1 : p;
    const auto [ptr, ec] = std::from_chars(q, end, value);
    if (ec != std::errc() || !(ends_token(ptr, end) || *ptr == '/')) return false;
    p = ptr;
    return true;
  }

  bool vertex(const char* p, const char* end) {
    double xyz[3];
    int count = 0;
    bool declined = false;
    while (next_token(p, end, declined)) {
      double value;
      if (!number(p, end, value)) return false;
      if (count < 3) xyz[count] = value;
      ++count;
    }
    // A fourth value is a rational weight (OBJ's `v x y z w`): the line-by-line reader keeps it.
    if (declined || count < 3 || count == 4) return false;
    for (double v : xyz)
      if (!std::isfinite(v)) return false;
    c_.positions.insert(c_.positions.end(), xyz, xyz + 3);
    ++c_.vertices;
    return true;
  }

  bool attribute(const char* p, const char* end, Slot& slot) {
    int count = 0;
    bool declined = false;
    while (next_token(p, end, declined)) {
      double value;
      if (!number(p, end, value) || !std::isfinite(value)) return false;
      slot.values.push_back(value);
      ++count;
    }
    if (declined || count < 1 || count > 3) return false;
    if (slot.components == 0) slot.components = count;
    if (count != slot.components) return false;
    ++slot.count;
    return true;
  }

  // A reference as vertex_reference reads it: 0-based if positive, chunk-local if negative
  // (`relative` set); false on anything the line-by-line reader reports.
  static bool reference(long long r, long long known, Index& value, bool& relative) {
    if (r == 0 || r > kIndexMax) return false;
    relative = r < 0;
    if (r < 0) {
      r += known;  // may be negative here: the vertices of the chunks before come first
      if (r < -kIndexMax) return false;
      value = Index(r);
    } else {
      value = Index(r - 1);
    }
    return true;
  }

  // The vt or vn part of a corner "v/vt/vn": if p is at a '/', the part after it, up to the
  // next '/' or the token's end; an empty or missing part means none.
  bool corner_attribute(const char*& p, const char* end, Slot& slot) {
    const bool has_part = p < end && *p == '/';
    if (has_part) ++p;
    const bool given = has_part && !(ends_token(p, end) || *p == '/');
    Index value = -1;
    if (given) {
      long long r;
      bool relative;
      if (!integer(p, end, r) || !reference(r, slot.count, value, relative)) return false;
      if (relative) slot.relative.push_back(slot.corners.size());
      else slot.largest = std::max<long long>(slot.largest, value);
    }
    (given ? slot.with : slot.without) = true;
    if (given) slot.corners.push_back(value);  // all corners or none: see below
    return !(slot.with && slot.without);  // some corners only: the reader's warning
  }

  bool face(const char* p, const char* end) {
    const std::size_t start = c_.face_vertices.size();
    bool declined = false;
    while (next_token(p, end, declined)) {
      long long r;
      Index value;
      bool relative;
      if (!integer(p, end, r) || !reference(r, c_.vertices, value, relative)) return false;
      if (relative) c_.relative.push_back(c_.face_vertices.size());
      else c_.largest = std::max<long long>(c_.largest, value);
      c_.face_vertices.push_back(value);
      if (!corner_attribute(p, end, c_.slots[0]) || !corner_attribute(p, end, c_.slots[1])) return false;
      while (!ends_token(p, end)) {  // the line-by-line reader ignores "/..." after vn
        if (*p == '\r') return false;
        ++p;
      }
    }
    if (declined || c_.face_vertices.size() - start < 3) return false;
    c_.face_ends.push_back(Index(c_.face_vertices.size()));
    return true;
  }

  Chunk& c_;
};

// Where each chunk's items start in the joined mesh.
struct Bases {
  Index vertices = 0, faces = 0, corners = 0, values[2] = {0, 0};
};

// The chunks' cut points: after a '\n' near every multiple of size / chunks.
std::vector<std::size_t> cut_points(std::string_view text, std::size_t chunks) {
  std::vector<std::size_t> cuts{0};
  for (std::size_t i = 1; i < chunks; ++i) {
    std::size_t at = std::max(cuts.back(), text.size() / chunks * i);
    at = text.find('\n', at);
    at = at == std::string_view::npos ? text.size() : at + 1;
    if (at > cuts.back() && at < text.size()) cuts.push_back(at);
  }
  cuts.push_back(text.size());
  return cuts;
}

// Joins the chunks in order, resolving relative references; false where the line-by-line
// reader would report an error or a warning.
bool join(std::vector<Chunk>& chunks, MeshData& mesh) {
  std::vector<Bases> bases(chunks.size() + 1);
  int components[2] = {0, 0};
  bool with[2] = {false, false}, without[2] = {false, false};
  long long sizes[5] = {0, 0, 0, 0, 0};  // vertices, faces, corners, vt, vn
  for (std::size_t k = 0; k < chunks.size(); ++k) {
    const Chunk& c = chunks[k];
    for (int s = 0; s < 2; ++s) {
      const Slot& slot = c.slots[s];
      if (slot.components && components[s] && slot.components != components[s]) return false;
      if (slot.components) components[s] = slot.components;
      with[s] |= slot.with, without[s] |= slot.without;
    }
    sizes[0] += c.vertices, sizes[1] += Index(c.face_ends.size()), sizes[2] += Index(c.face_vertices.size());
    sizes[3] += c.slots[0].count, sizes[4] += c.slots[1].count;
    for (long long size : sizes)
      if (size > kIndexMax) return false;
    bases[k + 1] = {Index(sizes[0]), Index(sizes[1]), Index(sizes[2]), {Index(sizes[3]), Index(sizes[4])}};
  }
  const Bases total = bases.back();
  for (int s = 0; s < 2; ++s)
    if (with[s] && without[s]) return false;
  for (std::size_t k = 0; k < chunks.size(); ++k) {
    const Chunk& c = chunks[k];
    if (c.largest >= total.vertices) return false;
    for (int s = 0; s < 2; ++s)
      if (with[s] && c.slots[s].largest >= total.values[s]) return false;
  }

  mesh.positions.resize(3 * std::size_t(total.vertices));
  grow(mesh.face_offsets, std::size_t(total.faces) + 1);
  grow(mesh.face_vertices, std::size_t(total.corners));
  std::vector<FaceVaryingArray> varying;
  const char* names[2] = {"uv", "normal"};
  const ArrayRole roles[2] = {ArrayRole::TextureCoordinates, ArrayRole::Normals};
  for (int s = 0; s < 2; ++s)
    if (with[s]) {
      varying.push_back({names[s], components[s], {}, {}, roles[s]});
      varying.back().values.resize(std::size_t(total.values[s]) * std::size_t(components[s]));
      varying.back().indices.resize(std::size_t(total.corners));
    }
  std::atomic<bool> ok = true;  // any task may clear it
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t k) {
    Chunk& c = chunks[k];
    const Bases& b = bases[k];
    std::copy(c.positions.begin(), c.positions.end(), mesh.positions.begin() + 3 * std::ptrdiff_t(b.vertices));
    for (std::size_t f = 0; f < c.face_ends.size(); ++f) mesh.face_offsets[std::size_t(b.faces) + f + 1] = b.corners + c.face_ends[f];
    for (std::size_t i : c.relative) {
      c.face_vertices[i] += b.vertices;
      if (c.face_vertices[i] < 0) ok = false;
    }
    std::copy(c.face_vertices.begin(), c.face_vertices.end(), mesh.face_vertices.begin() + b.corners);
    std::size_t array = 0;
    for (int s = 0; s < 2; ++s) {
      if (!with[s]) continue;
      Slot& slot = c.slots[s];
      FaceVaryingArray& out = varying[array++];
      for (std::size_t i : slot.relative) {
        slot.corners[i] += b.values[s];
        if (slot.corners[i] < 0) ok = false;
      }
      std::copy(slot.values.begin(), slot.values.end(),
                out.values.begin() + std::ptrdiff_t(b.values[s]) * components[s]);
      std::copy(slot.corners.begin(), slot.corners.end(), out.indices.begin() + b.corners);
    }
    c = Chunk();  // its memory back before the next
  });
  mesh.face_varying = std::move(varying);
  return ok;
}

}  // namespace

std::size_t obj_chunks_for(std::size_t bytes) {
  const std::size_t threads = std::size_t(std::max(1, tbb::this_task_arena::max_concurrency()));
  return std::clamp<std::size_t>(bytes >> 18, 1, 4 * threads);  // a quarter megabyte at least per chunk
}

std::optional<MeshData> parse_obj_fast(std::string_view text, std::size_t chunks) {
  const std::vector<std::size_t> cuts = cut_points(text, std::max<std::size_t>(chunks, 1));
  std::vector<Chunk> parsed(cuts.size() - 1);
  std::atomic<bool> ok = true;  // any task may clear it
  tbb::parallel_for(std::size_t(0), parsed.size(), [&](std::size_t k) {
    if (!ChunkParser(parsed[k]).parse(text.data() + cuts[k], text.data() + cuts[k + 1])) ok = false;
    read_advanced(cuts[k + 1] - cuts[k]);
  });
  MeshData mesh;
  if (!ok || !join(parsed, mesh)) return std::nullopt;
  return mesh;
}

bool obj_spec_statement(std::string_view keyword) {
  static constexpr std::string_view kSpec[] = {
      "vp",     "cstype", "deg",    "bmat",     "step",   "p",        "curv",   "curv2",      "surf",
      "parm",   "trim",   "hole",   "scrv",     "sp",     "end",      "con",    "g",          "s",
      "mg",     "o",      "bevel",  "c_interp", "d_interp", "lod",    "usemtl", "mtllib",     "shadow_obj",
      "trace_obj", "ctech", "stech", "call",    "csh",    "maplib",   "usemap", "res",        "bsp",
      "bzp",    "cdc",    "cdp"};
  return std::find(std::begin(kSpec), std::end(kSpec), keyword) != std::end(kSpec);
}

}  // namespace subdiv::io_detail
