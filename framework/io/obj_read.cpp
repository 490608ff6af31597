// Wavefront OBJ with Pixar's subdivision tags. Hand-written rather than OpenMesh's reader
// because that one drops or splits non-manifold faces and may reorder vertices; here every
// vertex and face reaches the engine exactly as written, so the engine can judge the
// topology and name the offending element.
//
// Read: v, f, l (any of the v, v/vt, v//vn, v/vt/vn forms; negative indices count back from
// the last vertex), and every tag of OpenSubdiv's OBJ files (regression/common/
// shape_utils.cpp, far/vtr tests' GetSdcOptions): t crease / t corner (vertex indices from
// 0), t hole (face indices from 0), and the options t interpolateboundary,
// t creasemethod, t smoothtriangles, t facevaryinginterpolateboundary and
// t facevaryingpropagatecorners, kept in MeshData::options. Hierarchical edits (t vertexedit,
// edgeedit, faceedit; gone from OpenSubdiv 3) are refused. Texture coordinates (vt) and
// normals (vn) with their own indices per face corner become face-varying arrays "uv" and
// "normal" (every face must then give them, as OpenSubdiv's channels require).
// Ignored: groups, materials, smoothing groups and other statements that do not change the
// surface.
//
// Large meshes (v, vt, vn and f only) go through the parallel fast path (obj_fast_parse.h),
// which gives the same MeshData; whatever it declines, errors included, is read here line by
// line, so every message names its file and line as before.
#include <span>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "framework/io/obj_fast_parse.h"
#include "framework/io/readers.h"
#include "framework/io/text_input.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {
namespace fs = std::filesystem;

namespace {

// A tag line "t name ints/floats/strings args...".
struct Tag {
  std::string_view name;
  std::vector<long long> ints;
  std::vector<double> floats;
  std::vector<std::string_view> strings;
};

class ObjReader {
public:
  explicit ObjReader(const fs::path& file) : file_(file) {}
  MeshData read(std::string_view text);

private:
  void statement(std::string_view keyword, Tokens& tokens);
  void vertex(Tokens& tokens);
  void finish_weights();
  void face(Tokens& tokens);
  void polyline(Tokens& tokens);
  void attribute(Tokens& tokens, int slot);
  void corner_attributes(std::string_view token);
  void finish_face_varying();
  void tag(Tokens& tokens);
  void crease_tag(const Tag& tag);
  void corner_tag(const Tag& tag);
  void hole_tag(const Tag& tag);
  void option_tag(const Tag& tag);
  void check_holes() const;
  Tag parse_tag(Tokens& tokens);
  Index vertex_reference(std::string_view token);
  double sharpness(double s, std::string_view tag);
  void check_forward_references() const;
  void check_tag_vertices() const;
  void check_creases_are_edges() const;
  void warn_unknown_statements();
  [[noreturn]] void fail(std::string_view message) const { fail_at(file_, line_, message); }

  const fs::path& file_;
  std::size_t line_ = 0;
  MeshData mesh_;
  // Positive references past the vertices defined so far: legal only if the vertex
  // appears further down, which is known only at the end.
  struct Reference {
    std::size_t line;
    long long index;
  };
  std::vector<Reference> forward_references_;
  std::vector<std::size_t> crease_lines_, corner_lines_, hole_lines_;  // for messages about tags
  // vt (slot 0) and vn (slot 1): the values, and per face corner the 0-based index or -1.
  struct Attribute {
    std::vector<double> values;
    int components = 0;
    std::vector<long long> corners;
    std::size_t line_with = 0, line_without = 0;  // a face line that gives it, one that does not
    long long largest = -1;                        // the largest index used, and where
    std::size_t largest_line = 0;
  };
  Attribute attributes_[2];
  struct Unknown {
    std::string keyword;
    std::size_t line;
  };
  std::vector<Unknown> unknown_;
  std::vector<double> weights_;  // the fourth coordinates read so far (1 before the first)
};

// `text` as a message may quote it (quoted_text.h: no terminal escapes, no NUL), cut at 40
// bytes.
std::string printable(std::string_view text) { return escaped(text.substr(0, 40)) + (text.size() > 40 ? "..." : ""); }

MeshData ObjReader::read(std::string_view text) {
  LineCursor lines(text);
  std::string_view raw;
  std::string joined;  // a statement continued over several lines with '\'
  bool continued = false;
  while (lines.next(raw)) {
    if (!continued) line_ = lines.line_number();  // messages name a statement's first line
    std::string_view line = strip_comment(raw);
    continued = !line.empty() && line.back() == '\\';
    if (continued || !joined.empty()) {
      joined.append(continued ? line.substr(0, line.size() - 1) : line).push_back(' ');
      if (continued) continue;
      line = joined;
    }
    Tokens tokens(line);
    std::string_view keyword;
    if (tokens.next(keyword)) statement(keyword, tokens);
    joined.clear();
  }
  if (!joined.empty()) {  // the last line ended in '\'
    Tokens tokens(joined);
    std::string_view keyword;
    if (tokens.next(keyword)) statement(keyword, tokens);
  }
  check_forward_references();
  check_tag_vertices();
  check_creases_are_edges();
  check_holes();
  finish_face_varying();
  finish_weights();
  warn_unknown_statements();
  return std::move(mesh_);
}

void ObjReader::statement(std::string_view keyword, Tokens& tokens) {
  if (keyword == "v") return vertex(tokens);
  if (keyword == "f") return face(tokens);
  if (keyword == "l") return polyline(tokens);
  if (keyword == "t") return tag(tokens);
  if (keyword == "vt") return attribute(tokens, 0);
  if (keyword == "vn") return attribute(tokens, 1);
  // The OBJ spec's other statements (g, o, s, usemtl, mtllib, free-form geometry) do not
  // describe the polygonal surface; skipping them is what every OBJ consumer does. Anything
  // else may be a face in disguise ("F 1 2 3", a NUL before "f"): skipped, but said.
  if (!obj_spec_statement(keyword)) unknown_.push_back({std::string(keyword), line_});
}

// One warning per unknown keyword, with its first lines.
void ObjReader::warn_unknown_statements() {
  std::vector<std::string> order;
  std::unordered_map<std::string, std::vector<std::size_t>> lines;
  for (const Unknown& u : unknown_) {
    auto& at = lines[u.keyword];
    if (at.empty()) order.push_back(u.keyword);
    at.push_back(u.line);
  }
  for (const std::string& keyword : order) {
    const std::vector<std::size_t>& at = lines[keyword];
    std::string where = fmt::format("line {}", at[0]);
    constexpr std::size_t kShown = 5;
    if (at.size() > 1) {
      where = "lines";
      for (std::size_t i = 0; i < std::min(at.size(), kShown); ++i) where += fmt::format("{}{}", i ? ", " : " ", at[i]);
      if (at.size() > kShown) where += fmt::format(" and {} more", at.size() - kShown);
    }
    mesh_.warnings.push_back(fmt::format("{}: {}: skipped the unknown statement {}; it is not part of the OBJ "
                                         "format (keywords are lower case: v, vt, vn, f, l, t, g, o, s, usemtl, ...)",
                                         escaped(file_.string()), where, subdiv::quoted(printable(keyword))));
  }
}

void ObjReader::vertex(Tokens& tokens) {
  double xyz[3], w = 1;
  std::string_view token;
  int count = 0;
  while (tokens.next(token)) {
    double value;
    if (!parse_double(token, value))
      fail(fmt::format("expected a number in 'v x y z', got {}", subdiv::quoted(token)));
    if (count < 3) xyz[count] = value;
    else if (count == 3) w = value;
    ++count;  // colours after xyz (6 or 7 values) are allowed and ignored
  }
  if (count < 3) fail(fmt::format("a vertex needs 3 coordinates 'v x y z', this one has {}", count));
  const Index number = mesh_.vertex_count() + 1;
  for (double c : xyz)
    if (!std::isfinite(c))
      fail(fmt::format("vertex {} has a non-finite coordinate ({}); fix or remove it", number, c));
  mesh_.positions.insert(mesh_.positions.end(), xyz, xyz + 3);
  // `v x y z w`: w is the weight of a rational control point; without it, 1 (the OBJ
  // specification, Appendix B1 of the Advanced Visualizer manual).
  if (count == 4) {
    if (!std::isfinite(w) || w <= 0)
      fail(fmt::format("vertex {} has the weight w = {}; the weights of rational control points ('v x y z w') must "
                       "be positive numbers",
                       number, w));
    weights_.resize(size_t(number - 1), 1.0);
    weights_.push_back(w);
  }
}

// The fourth coordinates as the point array "weight" (pipeline/rational_weights.h), 1 where
// a line has none.
void ObjReader::finish_weights() {
  if (weights_.empty()) return;
  weights_.resize(size_t(mesh_.vertex_count()), 1.0);
  mesh_.point_data.push_back({"weight", 1, std::move(weights_)});
}

// "7", "7/2", "7//3", "7/2/3", "-1": OBJ numbers from 1, negatives count back from the
// last vertex defined so far. Returns the 0-based index.
Index ObjReader::vertex_reference(std::string_view token) {
  const std::string_view head = token.substr(0, token.find('/'));
  long long r;
  if (!parse_integer(head, r))
    fail(fmt::format("expected a vertex number like 7, 7/2, 7//3 or 7/2/3, got {}", subdiv::quoted(token)));
  const long long known = mesh_.vertex_count();
  if (r == 0) fail("vertex number 0 is invalid: OBJ numbers vertices from 1");
  if (r < 0) {
    if (known + r < 0)
      fail(fmt::format("relative vertex number {} reaches before the first vertex: only {} "
                       "vertices are defined above this line",
                       r, known));
    return Index(known + r);
  }
  if (r > std::numeric_limits<Index>::max())
    fail(fmt::format("vertex number {} is too large (at most {})", r,
                     std::numeric_limits<Index>::max()));
  if (r > known) forward_references_.push_back({line_, r});
  return Index(r - 1);
}

// "vt u [v [w]]" (slot 0) or "vn x y z" (slot 1): every line of a kind must have as many
// numbers as the first.
void ObjReader::attribute(Tokens& tokens, int slot) {
  Attribute& a = attributes_[slot];
  const char* keyword = slot == 0 ? "vt" : "vn";
  std::string_view token;
  int count = 0;
  while (tokens.next(token)) {
    double value;
    if (!parse_double(token, value) || !std::isfinite(value))
      fail(fmt::format("expected a finite number in {}, got {}", subdiv::quoted(keyword), subdiv::quoted(token)));
    a.values.push_back(value);
    ++count;
  }
  if (count < 1 || count > 3) fail(fmt::format("{} takes 1 to 3 numbers, this one has {}", subdiv::quoted(keyword), count));
  if (a.components == 0) a.components = count;
  if (count != a.components)
    fail(fmt::format("this {} has {} numbers, the first one {}; give every {} the same count", subdiv::quoted(keyword), count,
                     a.components, keyword));
}

// The vt and vn numbers of a face corner "v/vt/vn" (either may be absent), 0-based.
void ObjReader::corner_attributes(std::string_view token) {
  for (int slot = 0; slot < 2; ++slot) {
    std::size_t at = token.find('/');
    for (int skip = 0; skip < slot && at != std::string_view::npos; ++skip) at = token.find('/', at + 1);
    std::string_view part = at == std::string_view::npos ? std::string_view() : token.substr(at + 1);
    part = part.substr(0, part.find('/'));
    Attribute& a = attributes_[slot];
    long long r = -1;
    if (!part.empty()) {
      if (!parse_integer(part, r) || r == 0)
        fail(fmt::format("{}: expected a {} number after the vertex number", subdiv::quoted(token), slot == 0 ? "vt" : "vn"));
      const long long known = (long long)(a.values.size() / std::max(1, a.components));
      r = r < 0 ? known + r : r - 1;
      if (r < 0) fail(fmt::format("{}: a relative {} number reaches before the first one", subdiv::quoted(token), slot == 0 ? "vt" : "vn"));
    }
    a.corners.push_back(r);
    std::size_t& seen = r >= 0 ? a.line_with : a.line_without;
    if (!seen) seen = line_;
    if (r > a.largest) a.largest = r, a.largest_line = line_;
  }
}

void ObjReader::finish_face_varying() {
  const char* names[2] = {"uv", "normal"};
  const ArrayRole roles[2] = {ArrayRole::TextureCoordinates, ArrayRole::Normals};
  for (int slot = 0; slot < 2; ++slot) {
    Attribute& a = attributes_[slot];
    if (!a.line_with) continue;
    const char* keyword = slot == 0 ? "vt" : "vn";
    if (a.line_without) {
      // A channel needs a value at every corner; a file that gives some only is still a mesh.
      mesh_.warnings.push_back(fmt::format("{}:{}: this face gives no {} number while the face on line {} does; the "
                                           "file's {} are left out (give every face one to keep them)",
                                           escaped(file_.string()), a.line_without, keyword, a.line_with, keyword));
      continue;
    }
    FaceVaryingArray f{names[slot], a.components, std::move(a.values), {}, roles[slot]};
    if (a.largest >= f.value_count())
      fail_at(file_, a.largest_line, fmt::format("this face uses {} number {}, but the file has {}", keyword,
                                                 a.largest + 1, f.value_count()));
    for (long long r : a.corners) f.indices.push_back(Index(r));
    mesh_.face_varying.push_back(std::move(f));
  }
}

void ObjReader::face(Tokens& tokens) {
  const std::size_t start = mesh_.face_vertices.size();
  std::string_view token;
  while (tokens.next(token)) {
    mesh_.face_vertices.push_back(vertex_reference(token));
    corner_attributes(token);
  }
  const std::size_t size = mesh_.face_vertices.size() - start;
  if (size < 3)
    fail(fmt::format("a face needs at least 3 vertices, this one has {}; remove the line or "
                     "write an edge as 'l a b'",
                     size));
  mesh_.face_offsets.push_back(Index(mesh_.face_vertices.size()));
}

void ObjReader::polyline(Tokens& tokens) {
  const std::size_t start = mesh_.line_vertices.size();
  std::string_view token;
  while (tokens.next(token)) mesh_.line_vertices.push_back(vertex_reference(token));
  const std::size_t size = mesh_.line_vertices.size() - start;
  if (size < 2)
    fail(fmt::format("a polyline 'l' needs at least 2 vertices, this one has {}", size));
  mesh_.line_offsets.push_back(Index(mesh_.line_vertices.size()));
}

// "t name i/f/s ints... floats... strings..." (Pixar's OBJ extension).
Tag ObjReader::parse_tag(Tokens& tokens) {
  Tag tag;
  std::string_view counts;
  if (!tokens.next(tag.name) || !tokens.next(counts))
    fail("expected a tag 't name ints/floats/strings values...', e.g. 't crease 2/1/0 0 1 10'");
  long long n[3] = {0, 0, 0};
  std::size_t at = 0;
  for (int k = 0; k < 3; ++k) {
    const std::size_t slash = k < 2 ? counts.find('/', at) : counts.size();
    if (slash == std::string_view::npos || !parse_integer(counts.substr(at, slash - at), n[k]) ||
        n[k] < 0)
      fail(fmt::format("tag {}: expected the argument counts as ints/floats/strings, e.g. "
                       "2/1/0, got {}",
                       subdiv::quoted(tag.name), subdiv::quoted(counts)));
    at = slash + 1;
  }
  std::string_view token;
  for (long long i = 0; i < n[0]; ++i) {
    long long v;
    if (!tokens.next(token) || !parse_integer(token, v))
      fail(fmt::format("tag {} announces {} integers ({}) but integer {} is {}", subdiv::quoted(tag.name), n[0],
                       counts, i + 1, token.empty() ? "missing" : fmt::format("{}", subdiv::quoted(token))));
    tag.ints.push_back(v);
    token = {};
  }
  for (long long i = 0; i < n[1]; ++i) {
    double v;
    if (!tokens.next(token) || !parse_double(token, v))
      fail(fmt::format("tag {} announces {} numbers ({}) after its integers but number {} "
                       "is {}",
                       subdiv::quoted(tag.name), n[1], counts, i + 1,
                       token.empty() ? "missing" : fmt::format("{}", subdiv::quoted(token))));
    tag.floats.push_back(v);
    token = {};
  }
  long long strings = 0;
  while (tokens.next(token)) ++strings, tag.strings.push_back(token);
  if (strings != n[2])
    fail(fmt::format("tag {} announces {} strings ({}) after its numbers but has {}",
                     subdiv::quoted(tag.name), n[2], counts, strings));
  return tag;
}

void ObjReader::tag(Tokens& tokens) {
  const Tag tag = parse_tag(tokens);
  if (tag.name == "crease") return crease_tag(tag);
  if (tag.name == "corner") return corner_tag(tag);
  if (tag.name == "hole") return hole_tag(tag);
  if (tag.name == "vertexedit" || tag.name == "edgeedit" || tag.name == "faceedit")
    fail(fmt::format("tag {} is a hierarchical edit, which OpenSubdiv 3 no longer supports and SubdivKit "
                     "does not either; remove the line (or apply the edit to the mesh itself)",
                     subdiv::quoted(tag.name)));
  option_tag(tag);
}

// "t hole 1/0/0 f ...": faces numbered from 0, as OpenSubdiv's shape_utils reads them.
void ObjReader::hole_tag(const Tag& tag) {
  if (tag.ints.empty()) fail("a hole tag needs at least one face: 't hole 1/0/0 face' (faces numbered from 0)");
  for (long long f : tag.ints) {
    mesh_.holes.push_back(Index(std::clamp<long long>(f, -1, std::numeric_limits<Index>::max())));
    hole_lines_.push_back(line_);
  }
}

// The option tags, with the values OpenSubdiv's shape_utils accepts.
void ObjReader::option_tag(const Tag& tag) {
  auto one_int = [&](long long lo, long long hi, const char* meaning) {
    if (tag.ints.size() != 1 || tag.ints[0] < lo || tag.ints[0] > hi)
      fail(fmt::format("tag {} takes one integer from {} to {} ({}), e.g. 't {} 1/0/0 {}'", subdiv::quoted(tag.name), lo, hi,
                       meaning, tag.name, lo));
    return int(tag.ints[0]);
  };
  auto one_string = [&](std::initializer_list<std::string_view> allowed) -> std::string {
    std::string names;
    for (auto a : allowed) names += (names.empty() ? "" : " or ") + std::string(a);
    if (tag.strings.size() == 1)
      for (auto a : allowed)
        if (tag.strings[0] == a) return std::string(a);
    fail(fmt::format("tag {} takes one string, {}, e.g. 't {} 0/0/1 {}'", subdiv::quoted(tag.name), names, tag.name,
                     *allowed.begin()));
  };
  MeshOptions& o = mesh_.options;
  if (tag.name == "interpolateboundary") {
    o.interpolate_boundary = one_int(0, 2, "0 none, 1 edges and corners, 2 edges only");
  } else if (tag.name == "facevaryinginterpolateboundary") {
    o.fvar_interpolate_boundary = one_int(0, 5, "OpenSubdiv's face-varying linear interpolation, 0 none to 5 all");
  } else if (tag.name == "facevaryingpropagatecorners") {
    o.fvar_propagate_corners = one_int(0, 1, "0 or 1");
  } else if (tag.name == "creasemethod") {
    o.crease_method = one_string({"normal", "chaikin"});
  } else if (tag.name == "smoothtriangles") {
    // OpenSubdiv 3 writes a string; Hbr-era files an integer (1: smooth).
    if (tag.strings.empty() && tag.ints.size() == 1) o.smooth_triangles = tag.ints[0] ? "smooth" : "catmark";
    else o.smooth_triangles = one_string({"smooth", "catmark"});
  } else {
    fail(fmt::format("tag {} is not one of OpenSubdiv's tags (crease, corner, hole, interpolateboundary, "
                     "creasemethod, smoothtriangles, facevaryinginterpolateboundary, facevaryingpropagatecorners); "
                     "remove the line",
                     subdiv::quoted(tag.name)));
  }
}

double ObjReader::sharpness(double s, std::string_view tag) {
  if (!std::isfinite(s) || s < 0)
    fail(fmt::format("{} sharpness {} is invalid; use a number >= 0 (0 smooth, 10 or more "
                     "infinitely sharp)",
                     tag, s));
  return s;
}

// Vertex pairs, as OpenSubdiv reads them: "t crease 2/1/0 a b s" or several pairs with
// one sharpness for all or one per pair.
void ObjReader::crease_tag(const Tag& tag) {
  const std::size_t pairs = tag.ints.size() / 2;
  if (tag.ints.empty() || tag.ints.size() % 2 != 0)
    fail(fmt::format("a crease tag needs pairs of vertices, got {} vertices; write one edge "
                     "per tag: 't crease 2/1/0 a b sharpness'",
                     tag.ints.size()));
  if (tag.floats.size() != 1 && tag.floats.size() != pairs)
    fail(fmt::format("a crease tag with {} edges needs 1 sharpness or {}, got {}", pairs, pairs,
                     tag.floats.size()));
  for (std::size_t p = 0; p < pairs; ++p) {
    const long long a = tag.ints[2 * p], b = tag.ints[2 * p + 1];
    if (a == b) fail(fmt::format("crease {}-{} joins a vertex to itself", a, b));
    const double s = sharpness(tag.floats[tag.floats.size() == 1 ? 0 : p], "crease");
    // Range is checked at the end, when the vertex count is final; clamp to keep the
    // value representable until then.
    auto narrow = [](long long v) {
      return Index(std::clamp<long long>(v, -1, std::numeric_limits<Index>::max()));
    };
    mesh_.creases.push_back({narrow(a), narrow(b), s});
    crease_lines_.push_back(line_);
  }
}

void ObjReader::corner_tag(const Tag& tag) {
  if (tag.ints.empty()) fail("a corner tag needs at least one vertex: 't corner 1/1/0 v sharpness'");
  if (tag.floats.size() != 1 && tag.floats.size() != tag.ints.size())
    fail(fmt::format("a corner tag with {} vertices needs 1 sharpness or {}, got {}",
                     tag.ints.size(), tag.ints.size(), tag.floats.size()));
  for (std::size_t i = 0; i < tag.ints.size(); ++i) {
    const double s = sharpness(tag.floats[tag.floats.size() == 1 ? 0 : i], "corner");
    const long long v = std::clamp<long long>(tag.ints[i], -1, std::numeric_limits<Index>::max());
    mesh_.corners.push_back({Index(v), s});
    corner_lines_.push_back(line_);
  }
}

void ObjReader::check_forward_references() const {
  const long long known = mesh_.vertex_count();
  for (const Reference& r : forward_references_)
    if (r.index > known)
      fail_at(file_, r.line,
              fmt::format("refers to vertex {}, but the file defines only {} vertices "
                          "(OBJ numbers them from 1)",
                          r.index, known));
}

void ObjReader::check_tag_vertices() const {
  const Index n = mesh_.vertex_count();
  auto check = [&](Index v, std::size_t line, const char* what) {
    if (v < 0 || v >= n)
      fail_at(file_, line,
              fmt::format("{} tag names vertex {}, which does not exist: the file has {} "
                          "vertices and tags number them from 0 (0 to {})",
                          what, v, n, n - 1));
  };
  for (std::size_t i = 0; i < mesh_.creases.size(); ++i) {
    check(mesh_.creases[i].v0, crease_lines_[i], "crease");
    check(mesh_.creases[i].v1, crease_lines_[i], "crease");
  }
  for (std::size_t i = 0; i < mesh_.corners.size(); ++i)
    check(mesh_.corners[i].v, corner_lines_[i], "corner");
}

void ObjReader::check_holes() const {
  for (std::size_t i = 0; i < mesh_.holes.size(); ++i)
    if (mesh_.holes[i] < 0 || mesh_.holes[i] >= mesh_.face_count())
      fail_at(file_, hole_lines_[i],
              fmt::format("hole tag names face {}, which does not exist: the file has {} faces and tags number "
                          "them from 0 (0 to {})",
                          mesh_.holes[i], mesh_.face_count(), mesh_.face_count() - 1));
}

// A crease on a pair of vertices that no face or polyline joins would be silently
// ignored by any refiner; this is almost always an off-by-one (1-based indices in tags).
void ObjReader::check_creases_are_edges() const {
  if (mesh_.creases.empty()) return;
  auto key = [](Index a, Index b) {
    return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
  };
  std::unordered_map<std::uint64_t, bool> found;
  for (const CreaseTag& c : mesh_.creases) found[key(c.v0, c.v1)] = false;
  auto mark = [&](std::span<const Index> offsets, std::span<const Index> verts, bool closed) {
    for (std::size_t f = 0; f + 1 < offsets.size(); ++f)
      for (Index k = offsets[f]; k < offsets[f + 1]; ++k) {
        const bool last = k + 1 == offsets[f + 1];
        if (last && !closed) break;
        const auto it = found.find(key(verts[k], verts[last ? offsets[f] : k + 1]));
        if (it != found.end()) it->second = true;
      }
  };
  mark(mesh_.face_offsets, mesh_.face_vertices, true);
  mark(mesh_.line_offsets, mesh_.line_vertices, false);
  for (std::size_t i = 0; i < mesh_.creases.size(); ++i) {
    const CreaseTag& c = mesh_.creases[i];
    if (!found[key(c.v0, c.v1)])
      fail_at(file_, crease_lines_[i],
              fmt::format("crease {}-{} is not an edge of any face or polyline; tags number "
                          "vertices from 0 (OBJ faces from 1), so check for an off-by-one",
                          c.v0, c.v1));
  }
}

}  // namespace

MeshData read_obj(const fs::path& file) {
  const std::string text = read_whole_file(file);
  if (std::optional<MeshData> mesh = parse_obj_fast(without_utf8_bom(text), obj_chunks_for(text.size())))
    return std::move(*mesh);
  return ObjReader(file).read(text);
}

MeshData read_obj_line_by_line(const fs::path& file) { return ObjReader(file).read(read_whole_file(file)); }

}  // namespace subdiv::io_detail
