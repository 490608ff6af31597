#include "framework/io/feature_file.h"

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <nlohmann/json.hpp>

#include "framework/io/mesh_level.h"
#include "framework/io/text_input.h"
#include "framework/util/error.h"
#include "framework/util/input_errors.h"
#include "framework/util/input_file.h"
#include "framework/util/json_text_check.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

using Json = nlohmann::json;

constexpr float kInfinite = 10.f;

class Parser {
public:
  explicit Parser(std::string source) { tags_.source = std::move(source); }

  FeatureTags parse(const Json& root) {
    if (!root.is_object())
      fail("", fmt::format("the file must hold a JSON object with \"creases\" and/or \"corners\", not {}",
                           describe(root)));
    for (const auto& [key, value] : root.items()) {
      if (key == "creases") creases(value);
      else if (key == "corners") corners(value);
      else if (key == "holes") holes(value);
      else if (key != "description" && key != "$schema")
        fail(key, "unknown key; a feature file has \"creases\", \"corners\" and \"holes\" (and optionally \"description\")");
    }
    return std::move(tags_);
  }

private:
  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    if (where.empty()) throw Error(fmt::format("{}: {}", tags_.source, problem));
    throw Error(fmt::format("{}: {}: {}", tags_.source, where, problem));
  }

  static std::string describe(const Json& j) {
    std::string text = j.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return fmt::format("{} {}", j.type_name(), text);
  }

  const Json& list(const Json& value, const std::string& where) const {
    if (!value.is_array()) fail(where, fmt::format("expected a list of entries, got {}", describe(value)));
    return value;
  }

  Index vertex(const Json& value, const std::string& where) const {
    const bool whole = value.is_number_integer() ||
                       (value.is_number_float() && std::floor(value.get<double>()) == value.get<double>());
    if (!whole) fail(where, fmt::format("a vertex index must be a whole number >= 0 (0-based), got {}", describe(value)));
    const double v = value.get<double>();
    if (v < 0 || v > double(std::numeric_limits<Index>::max()))
      fail(where, fmt::format("vertex index {} is out of range; indices are 0-based and >= 0", value.dump()));
    return Index(v);
  }

  float sharpness(const Json& entry, const std::string& where) const {
    const auto it = entry.find("sharpness");
    if (it == entry.end()) return kInfinite;
    const std::string at = where + ".sharpness";
    if (it->is_string()) {
      if (it->get<std::string>() == "infinite") return kInfinite;
      fail(at, fmt::format("expected a number >= 0 or \"infinite\", got {}", describe(*it)));
    }
    if (!it->is_number()) fail(at, fmt::format("expected a number >= 0 or \"infinite\", got {}", describe(*it)));
    const double s = it->get<double>();
    if (!std::isfinite(s)) fail(at, "sharpness must be finite; write \"infinite\" for an infinitely sharp feature");
    if (s < 0)
      fail(at, fmt::format("sharpness {} is negative; sharpness must be >= 0 (0 smooth, 10 or \"infinite\" "
                           "infinitely sharp)", it->dump()));
    return float(std::min(s, double(std::numeric_limits<float>::max())));
  }

  void check_keys(const Json& entry, const std::string& where, std::initializer_list<const char*> allowed) const {
    if (!entry.is_object()) fail(where, fmt::format("expected an object, got {}", describe(entry)));
    for (const auto& [key, value] : entry.items()) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || key == a;
      if (!ok) {
        std::string names;
        for (const char* a : allowed) names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", escaped(a));
        fail(where, fmt::format("unknown key \"{}\"; an entry here may have {}", escaped(key), names));
      }
    }
  }

  void creases(const Json& value) {
    const Json& all = list(value, "creases");
    for (size_t i = 0; i < all.size(); ++i) {
      const std::string where = fmt::format("creases[{}]", i);
      const Json& entry = all[i];
      check_keys(entry, where, {"edge", "path", "sharpness"});
      const bool edge = entry.contains("edge"), path = entry.contains("path");
      if (edge == path)
        fail(where, "a crease has either \"edge\": [v0, v1] or \"path\": [v0, v1, v2, ...]");
      const float s = sharpness(entry, where);
      const std::string key = edge ? "edge" : "path";
      const Json& vs = entry[key];
      if (!vs.is_array()) fail(where + "." + key, fmt::format("expected a list of vertex indices, got {}", describe(vs)));
      if (edge && vs.size() != 2)
        fail(where + ".edge", fmt::format("an edge has two end points, got {}; use \"path\" for a walk along "
                                          "several edges", vs.size()));
      if (path && vs.size() < 2)
        fail(where + ".path", fmt::format("a path needs at least two vertices, got {}", vs.size()));
      Index previous = vertex(vs[0], fmt::format("{}.{}[0]", where, key));
      for (size_t k = 1; k < vs.size(); ++k) {
        const Index v = vertex(vs[k], fmt::format("{}.{}[{}]", where, key, k));
        const std::string at = edge ? where + ".edge" : fmt::format("{}.path[{}..{}]", where, k - 1, k);
        if (v == previous) fail(at, fmt::format("joins vertex {} to itself", v));
        tags_.creases.push_back({previous, v, s, at});
        previous = v;
      }
    }
  }

  void corners(const Json& value) {
    const Json& all = list(value, "corners");
    for (size_t i = 0; i < all.size(); ++i) {
      const std::string where = fmt::format("corners[{}]", i);
      const Json& entry = all[i];
      check_keys(entry, where, {"vertex", "vertices", "sharpness"});
      const bool one = entry.contains("vertex"), many = entry.contains("vertices");
      if (one == many) fail(where, "a corner has either \"vertex\": v or \"vertices\": [v0, v1, ...]");
      const float s = sharpness(entry, where);
      if (one) {
        tags_.corners.push_back({vertex(entry["vertex"], where + ".vertex"), s, where + ".vertex"});
        continue;
      }
      const Json& vs = entry["vertices"];
      if (!vs.is_array()) fail(where + ".vertices", fmt::format("expected a list of vertex indices, got {}", describe(vs)));
      for (size_t k = 0; k < vs.size(); ++k) {
        const std::string at = fmt::format("{}.vertices[{}]", where, k);
        tags_.corners.push_back({vertex(vs[k], at), s, at});
      }
    }
  }

  // "holes": [3, 7]: faces, 0-based, that shape their neighbours but are left out of the surface.
  void holes(const Json& value) {
    if (!value.is_array()) fail("holes", fmt::format("expected a list of face indices, got {}", describe(value)));
    for (size_t i = 0; i < value.size(); ++i) {
      const std::string where = fmt::format("holes[{}]", i);
      tags_.holes.push_back({vertex(value[i], where), where});
    }
  }

  FeatureTags tags_;
};

}  // namespace

FeatureTags parse_feature_json(const std::string& text, const std::string& source) {
  check_json_text(text, source);  // depth and number range, with their places
  Json root;
  try {
    root = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw Error(json_syntax_error(text, source, e.byte, e.what(), " in the feature file"));
  } catch (const Json::exception& e) {  // anything check_json_text did not foresee
    throw Error(fmt::format("{}: JSON the parser refuses in the feature file: {}", source, e.what()));
  }
  return Parser(source).parse(root);
}

FeatureTags read_feature_file(const std::filesystem::path& file) {
  return naming_file_on_failure(file.string(),
                                [&] { return parse_feature_json(read_input_file(file, "feature"), file.string()); });
}

void apply_feature_tags(const FeatureTags& tags, Level& level) {
  // Check everything first so that a refused file leaves the level as it was.
  std::vector<Index> edges(tags.creases.size());
  for (size_t i = 0; i < tags.creases.size(); ++i) {
    const auto& c = tags.creases[i];
    for (Index v : {c.v0, c.v1})
      if (v >= level.vertex_count)
        throw Error(fmt::format("{}: {}: vertex {} does not exist; the mesh has {} vertices, numbered from 0",
                                tags.source, c.where, v, level.vertex_count));
    edges[i] = find_edge(level, c.v0, c.v1);
    if (edges[i] == kNone)
      throw Error(fmt::format("{}: {}: vertices {} and {} are not joined by an edge of the mesh; a crease must "
                              "name the two end points of an edge (0-based vertex indices)",
                              tags.source, c.where, c.v0, c.v1));
  }
  for (const auto& c : tags.corners)
    if (c.v >= level.vertex_count)
      throw Error(fmt::format("{}: {}: vertex {} does not exist; the mesh has {} vertices, numbered from 0",
                              tags.source, c.where, c.v, level.vertex_count));
  for (const auto& h : tags.holes)
    if (h.face >= level.face_count())
      throw Error(fmt::format("{}: {}: face {} does not exist; the mesh has {} faces, numbered from 0", tags.source,
                              h.where, h.face, level.face_count()));
  if (!tags.creases.empty() && level.edge_sharpness.empty()) level.edge_sharpness.assign(level.edge_count(), 0.f);
  for (size_t i = 0; i < tags.creases.size(); ++i) level.edge_sharpness[edges[i]] = tags.creases[i].sharpness;
  if (!tags.corners.empty() && level.vertex_sharpness.empty()) level.vertex_sharpness.assign(level.vertex_count, 0.f);
  for (const auto& c : tags.corners) level.vertex_sharpness[c.v] = c.sharpness;
  if (!tags.holes.empty() && level.face_hole.empty()) level.face_hole.assign(level.face_count(), 0);
  for (const auto& h : tags.holes) level.face_hole[h.face] = 1;
  require_some_face_outside_holes(level, tags.source);
}

}  // namespace subdiv
