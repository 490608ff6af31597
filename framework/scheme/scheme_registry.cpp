#include "framework/scheme/scheme_registry.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <fmt/format.h>
#include <mutex>

#include "framework/scheme/json_source.h"
#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_folders.h"
#include "framework/scheme/scheme_loader.h"
#include "framework/util/error.h"
#include "framework/util/option_spelling.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace fs = std::filesystem;
namespace {

// Schemes registered in code (plugins). A deque keeps entries in place while others are
// added; they are registered before any refinement starts.
struct CodeSchemes {
  std::mutex mutex;
  std::deque<CodeSchemeEntry> entries;
};

CodeSchemes& code_schemes() {
  static CodeSchemes c;
  return c;
}

std::vector<fs::path> scheme_directories() {
  std::vector<fs::path> dirs;
  for (auto& folder : scheme_folders()) dirs.push_back(std::move(folder.path));
  return dirs;
}

// Whether anything is at p; false also for a path the system cannot look up (a name longer
// than the file system allows, a loop of links), which then reads as "no such scheme".
bool path_exists(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec);
}

bool looks_like_path(const std::string& s) {
  return s.find('/') != std::string::npos || (s.size() > 5 && s.ends_with(".json"));
}

fs::path find_scheme_file(const std::string& name_or_path, const fs::path& relative_to = {}) {
  if (looks_like_path(name_or_path)) {
    fs::path p = name_or_path;
    if (p.is_relative() && !relative_to.empty() && path_exists(relative_to / p)) p = relative_to / p;
    if (!path_exists(p)) throw Error(fmt::format("scheme file {} does not exist", subdiv::quoted(name_or_path)));
    return p;
  }
  for (const auto& dir : scheme_directories()) {
    fs::path candidate = dir / (name_or_path + ".json");
    if (path_exists(candidate)) return candidate;
  }
  if (find_code_scheme(name_or_path))
    throw Error(fmt::format("scheme {} is defined by a plugin, not a file", subdiv::quoted(name_or_path)));
  std::string known;
  for (const auto& s : list_schemes()) known += (known.empty() ? "" : ", ") + s.name;
  throw Error(fmt::format("unknown scheme {}; the schemes are: {} (or give a path to a .json file)",
                          subdiv::quoted(name_or_path), known));
}

std::shared_ptr<const CurveScheme> resolve_curve(const std::string& name, const fs::path& referring_file,
                                                 const ParameterOverrides& overrides,
                                                 std::set<std::string>* used) {
  if (const CodeSchemeEntry* code = looks_like_path(name) ? nullptr : find_code_scheme(name)) {
    if (code->kind != "curve")
      throw Error(fmt::format("{} is a surface scheme ({}); name a curve scheme", subdiv::quoted(name), code->origin));
    return code->make_curve(overrides, used);
  }
  const fs::path file = find_scheme_file(name, referring_file.parent_path());
  if (scheme_file_kind(file) != "curve")
    throw Error(fmt::format("{} is a surface scheme; name a curve scheme", subdiv::quoted(name)));
  return load_curve_scheme(file, overrides, used);
}

}  // namespace

std::string scheme_file_path(const std::string& name_or_path) { return find_scheme_file(name_or_path).string(); }

std::string scheme_argument(const Scheme& scheme) {
  if (scheme.path.empty() || find_code_scheme(scheme.name)) return scheme.name;
  try {
    std::error_code ec;
    if (fs::equivalent(find_scheme_file(scheme.name), scheme.path, ec) && !ec) return scheme.name;
  } catch (const Error&) {
  }
  return scheme.path;
}

std::string scheme_plugin_options(const Scheme& scheme) {
  std::vector<std::string> origins;
  if (const CodeSchemeEntry* code = find_code_scheme(scheme.name)) origins.push_back(code->origin);
  for (const StepRules& step : scheme.steps) origins.push_back(splitter_info(step.split).origin);
  std::vector<std::string> files;
  CodeSchemes& c = code_schemes();
  const std::lock_guard lock(c.mutex);
  for (const std::string& origin : origins)
    for (const CodeSchemeEntry& e : c.entries)  // a plugin's file is known through what it registered
      if (e.origin == origin && std::find(files.begin(), files.end(), e.path) == files.end()) files.push_back(e.path);
  std::string out;
  for (const std::string& f : files) out += " --plugin " + f;
  return out;
}

std::shared_ptr<const Scheme> load_scheme(const std::string& name_or_path, const ParameterOverrides& overrides) {
  if (const CodeSchemeEntry* code = looks_like_path(name_or_path) ? nullptr : find_code_scheme(name_or_path)) {
    if (code->kind != "surface")
      throw Error(fmt::format("{} is a curve scheme ({}); surface refinement needs a surface scheme", subdiv::quoted(name_or_path),
                              code->origin));
    return code->make_surface(overrides);
  }
  const fs::path file = find_scheme_file(name_or_path);
  if (scheme_file_kind(file) != "surface")
    throw Error(fmt::format("{} is a curve scheme; surface refinement needs a surface scheme", file.string()));
  return load_surface_scheme(file, overrides, resolve_curve);
}

std::shared_ptr<const CurveScheme> load_curve(const std::string& name_or_path, const ParameterOverrides& overrides,
                                              std::set<std::string>* used) {
  std::set<std::string> taken;
  std::shared_ptr<const CurveScheme> curve;
  if (const CodeSchemeEntry* code = looks_like_path(name_or_path) ? nullptr : find_code_scheme(name_or_path)) {
    if (code->kind != "curve")
      throw Error(fmt::format("{} is a surface scheme ({}); name a curve scheme", subdiv::quoted(name_or_path), code->origin));
    curve = code->make_curve(overrides, &taken);
  } else {
    const fs::path file = find_scheme_file(name_or_path);
    if (scheme_file_kind(file) != "curve")
      throw OptionError(fmt::format("{} is a surface scheme; polylines need a curve scheme ({{scheme_list}} lists the "
                                    "curve schemes)",
                                    file.string()));
    curve = load_curve_scheme(file, overrides, &taken);
  }
  if (used) used->insert(taken.begin(), taken.end());
  else
    for (const auto& [name, value] : overrides)
      if (!taken.count(name))
        throw OptionError(fmt::format("{}: the scheme has no parameter {} (from {{param}} {}={}); {{scheme_list}} "
                                      "lists each scheme's parameters",
                                      curve->path, subdiv::quoted(name), name, value));
  return curve;
}

std::shared_ptr<const Scheme> load_scheme_text(const std::string& text, const std::string& label,
                                               const ParameterOverrides& overrides) {
  if (scheme_text_kind(text, label) != "surface")
    throw Error(fmt::format("{} is a curve scheme; surface refinement needs a surface scheme", label));
  return load_surface_scheme_text(text, label, overrides, resolve_curve);
}

std::shared_ptr<const CurveScheme> load_curve_text(const std::string& text, const std::string& label,
                                                   const ParameterOverrides& overrides, std::set<std::string>* used) {
  if (scheme_text_kind(text, label) != "curve")
    throw Error(fmt::format("{} is a surface scheme; name a curve scheme", label));
  std::set<std::string> taken;
  auto curve = load_curve_scheme_text(text, label, overrides, &taken);
  if (used) used->insert(taken.begin(), taken.end());
  else
    for (const auto& [name, value] : overrides)
      if (!taken.count(name))
        throw OptionError(fmt::format("{}: the scheme has no parameter {} (from {{param}} {}={})", label, subdiv::quoted(name), name,
                                      value));
  return curve;
}

void register_code_scheme(CodeSchemeEntry entry) {
  if (entry.name.empty()) throw Error("a scheme needs a name");
  if (entry.kind != "surface" && entry.kind != "curve")
    throw Error(fmt::format("scheme {}: kind {} is not one of: surface, curve", subdiv::quoted(entry.name), subdiv::quoted(entry.kind)));
  if ((entry.kind == "surface" && !entry.make_surface) || (entry.kind == "curve" && !entry.make_curve))
    throw Error(fmt::format("scheme {} has no function that makes it", subdiv::quoted(entry.name)));
  if (looks_like_path(entry.name) || entry.name.find_first_of(":, ") != std::string::npos)
    throw Error(fmt::format("{} cannot be a scheme name: no '/', ':', ',' or spaces, no .json ending", subdiv::quoted(entry.name)));
  if (const CodeSchemeEntry* other = find_code_scheme(entry.name))
    throw Error(fmt::format("duplicate scheme name {}: {} already defines it", subdiv::quoted(entry.name), other->origin));
  for (const auto& dir : scheme_directories())
    if (fs::path file = dir / (entry.name + ".json"); path_exists(file))
      throw Error(fmt::format("duplicate scheme name {}: the scheme file {} already defines it", subdiv::quoted(entry.name),
                              file.string()));
  CodeSchemes& c = code_schemes();
  std::lock_guard lock(c.mutex);
  c.entries.push_back(std::move(entry));
}

void unregister_code_scheme(const std::string& name) {
  CodeSchemes& c = code_schemes();
  std::lock_guard lock(c.mutex);
  // Only the last entry: erasing elsewhere would move the others, which callers point to.
  if (c.entries.empty() || c.entries.back().name != name)
    throw Error("unregister_code_scheme: only the most recently registered scheme can be removed");
  c.entries.pop_back();
}

const CodeSchemeEntry* find_code_scheme(const std::string& name) {
  CodeSchemes& c = code_schemes();
  std::lock_guard lock(c.mutex);
  for (const auto& e : c.entries)
    if (e.name == name) return &e;
  return nullptr;
}

std::string scheme_kind(const std::string& name_or_path) {
  if (!looks_like_path(name_or_path))
    if (const CodeSchemeEntry* code = find_code_scheme(name_or_path)) return code->kind;
  return scheme_file_kind(find_scheme_file(name_or_path));
}

std::vector<SchemeListing> list_schemes() {
  std::vector<SchemeListing> found;
  {
    CodeSchemes& c = code_schemes();
    std::lock_guard lock(c.mutex);
    for (const auto& e : c.entries) found.push_back({e.name, e.description, e.path, e.kind, e.origin});
  }
  for (const auto& folder : scheme_folders()) {
    const fs::path& dir = folder.path;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      if (entry.path().extension() != ".json" || entry.path().filename() == "scheme.schema.json") continue;
      const std::string name = entry.path().stem().string();
      if (std::any_of(found.begin(), found.end(), [&](auto& s) { return s.name == name; })) continue;
      SchemeListing listing{name, "", entry.path().string(), "surface", folder.origin};
      try {
        const auto root = read_json_file(entry.path());
        listing.description = root.value("description", "");
        listing.kind = root.value("kind", "surface");
      } catch (const std::exception& e) {
        // One broken file must not hide the others: list it with the reason.
        listing.description = std::string("(unreadable: ") + e.what() + ")";
        listing.kind = "surface";
      }
      found.push_back(std::move(listing));
    }
  }
  std::sort(found.begin(), found.end(), [](auto& a, auto& b) { return a.name < b.name; });
  return found;
}

}  // namespace subdiv
