#include "framework/scheme/scheme_registry.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>

#include "framework/scheme/json_source.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/util/error.h"

namespace subdiv {
namespace fs = std::filesystem;
namespace {

// Search order: $SUBDIV_SCHEME_PATH (':'-separated), the source tree's schemes/, the
// installed share/subdivkit/schemes.
std::vector<fs::path> scheme_directories() {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("SUBDIV_SCHEME_PATH")) {
    std::string list = env;
    size_t start = 0;
    while (start <= list.size()) {
      size_t end = list.find(':', start);
      if (end == std::string::npos) end = list.size();
      if (end > start) dirs.emplace_back(list.substr(start, end - start));
      start = end + 1;
    }
  }
  dirs.emplace_back(SUBDIV_SCHEME_DIR_BUILD);
  dirs.emplace_back(SUBDIV_SCHEME_DIR_INSTALL);
  return dirs;
}

bool looks_like_path(const std::string& s) {
  return s.find('/') != std::string::npos || (s.size() > 5 && s.ends_with(".json"));
}

fs::path find_scheme_file(const std::string& name_or_path, const fs::path& relative_to = {}) {
  if (looks_like_path(name_or_path)) {
    fs::path p = name_or_path;
    if (p.is_relative() && !relative_to.empty() && fs::exists(relative_to / p)) p = relative_to / p;
    if (!fs::exists(p)) throw Error(fmt::format("scheme file '{}' does not exist", name_or_path));
    return p;
  }
  for (const auto& dir : scheme_directories()) {
    fs::path candidate = dir / (name_or_path + ".json");
    if (fs::exists(candidate)) return candidate;
  }
  std::string known;
  for (const auto& s : list_schemes()) known += (known.empty() ? "" : ", ") + s.name;
  throw Error(fmt::format("unknown scheme '{}'; the schemes are: {} (or give a path to a .json file)",
                          name_or_path, known));
}

std::shared_ptr<const CurveScheme> resolve_curve(const std::string& name, const fs::path& referring_file,
                                                 const ParameterOverrides& overrides,
                                                 std::set<std::string>* used) {
  const fs::path file = find_scheme_file(name, referring_file.parent_path());
  if (scheme_file_kind(file) != "curve")
    throw Error(fmt::format("{}: \"curve\": '{}' is a surface scheme; name a curve scheme",
                            referring_file.string(), name));
  return load_curve_scheme(file, overrides, used);
}

}  // namespace

std::shared_ptr<const Scheme> load_scheme(const std::string& name_or_path, const ParameterOverrides& overrides) {
  const fs::path file = find_scheme_file(name_or_path);
  if (scheme_file_kind(file) != "surface")
    throw Error(fmt::format("{} is a curve scheme; surface refinement needs a surface scheme", file.string()));
  return load_surface_scheme(file, overrides, resolve_curve);
}

std::shared_ptr<const CurveScheme> load_curve(const std::string& name_or_path, const ParameterOverrides& overrides) {
  const fs::path file = find_scheme_file(name_or_path);
  if (scheme_file_kind(file) != "curve")
    throw Error(fmt::format("{} is a surface scheme; polylines need a curve scheme (`subdiv schemes` lists them, "
                            "e.g. chaikin, cubic-bspline, four-point)", file.string()));
  std::set<std::string> used;
  auto curve = load_curve_scheme(file, overrides, &used);
  for (const auto& [name, value] : overrides)
    if (!used.count(name))
      throw Error(fmt::format("{}: the scheme has no parameter '{}' (from --param {}={}); `subdiv schemes` lists "
                              "each scheme's parameters",
                              file.string(), name, name, value));
  return curve;
}

std::string scheme_kind(const std::string& name_or_path) { return scheme_file_kind(find_scheme_file(name_or_path)); }

std::vector<SchemeListing> list_schemes() {
  std::vector<SchemeListing> found;
  for (const auto& dir : scheme_directories()) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      if (entry.path().extension() != ".json" || entry.path().filename() == "scheme.schema.json") continue;
      const std::string name = entry.path().stem().string();
      if (std::any_of(found.begin(), found.end(), [&](auto& s) { return s.name == name; })) continue;
      SchemeListing listing{name, "", entry.path().string(), "surface"};
      try {
        const auto root = read_json_file(entry.path());
        listing.description = root.value("description", "");
        listing.kind = root.value("kind", "surface");
      } catch (const Error& e) {
        listing.description = std::string("(unreadable: ") + e.what() + ")";
      }
      found.push_back(std::move(listing));
    }
  }
  std::sort(found.begin(), found.end(), [](auto& a, auto& b) { return a.name < b.name; });
  return found;
}

}  // namespace subdiv
