#include "framework/plugin/plugin_loader.h"

#include <algorithm>
#include <cstdlib>
#include <dlfcn.h>
#include <fmt/format.h>
#include <mutex>
#include <set>
#include <string_view>

#include "framework/plugin/elf_check.h"
#include "framework/plugin/plugin_api.h"
#include "framework/util/error.h"
#include "framework/util/library_location.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace fs = std::filesystem;

static_assert(std::string_view(SUBDIVKIT_VERSION_STRING) == std::string_view(SUBDIV_VERSION),
              "plugin_api.h: SUBDIVKIT_VERSION_STRING must match the project version in CMakeLists.txt");

namespace {

constexpr const char* kLibrarySuffix = ".so";

struct LoaderState {
  std::mutex mutex;
  std::vector<PluginStatus> statuses;
  std::set<std::string> tried;  // canonical paths
  std::vector<void*> handles;   // loaded plugins stay open for the life of the process
};

LoaderState& state() {
  static LoaderState s;
  return s;
}

bool valid_plugin_name(std::string_view name) {
  if (name.empty() || name.size() > 64) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
  });
}

std::string text_or(const char* s, const char* fallback) { return s ? std::string(s) : std::string(fallback); }

// Loads one library; fills `status`. Returns the handle to keep, or null (closed) when refused.
void* try_load(const fs::path& file, PluginStatus& status, const std::vector<PluginStatus>& loaded_so_far) {
  auto refuse = [&](std::string reason) -> void* {
    status.loaded = false;
    status.reason = std::move(reason);
    return nullptr;
  };
  std::error_code ec;
  if (!fs::exists(file, ec)) return refuse("no such file");
  if (const auto problem = plugin_file_problem(file)) return refuse(*problem);
  dlerror();
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) return refuse(fmt::format("cannot load the library: {}", text_or(dlerror(), "unknown error")));
  auto close_and_refuse = [&](std::string reason) -> void* {
    dlclose(handle);
    return refuse(std::move(reason));
  };
  auto entry = reinterpret_cast<SubdivPluginInfoFunction>(dlsym(handle, SUBDIV_PLUGIN_ENTRY_POINT));
  if (!entry)
    return close_and_refuse(fmt::format("no entry point {}: not a SubdivKit plugin (a plugin defines it with "
                                        "SUBDIV_PLUGIN(name, version, register) from framework/plugin/plugin_api.h)",
                                        subdiv::quoted(SUBDIV_PLUGIN_ENTRY_POINT)));
  const SubdivPluginInfo* info = nullptr;
  try {
    info = entry();
  } catch (const std::exception& e) {
    return close_and_refuse(fmt::format("its entry point threw: {}", e.what()));
  } catch (...) {
    return close_and_refuse("its entry point threw an exception");
  }
  if (!info) return close_and_refuse("its entry point returned no plugin record");
  status.name = text_or(info->name, "");
  status.version = text_or(info->version, "");
  if (info->interface_version != SUBDIV_PLUGIN_INTERFACE_VERSION)
    return close_and_refuse(fmt::format(
        "interface version mismatch: the plugin was built for plugin interface {} (SubdivKit {}), this SubdivKit {} "
        "speaks interface {}; rebuild the plugin against this SubdivKit",
        info->interface_version, escaped(text_or(info->subdivkit_version, "unknown")), SUBDIVKIT_VERSION_STRING,
        SUBDIV_PLUGIN_INTERFACE_VERSION));
  if (!valid_plugin_name(status.name))
    return close_and_refuse(fmt::format("invalid plugin name {}: use 1 to 64 letters, digits, '-', '_' or '.'",
                                        subdiv::quoted(status.name)));
  if (!info->register_plugin) return close_and_refuse("the plugin record has no registration function");
  for (const PluginStatus& other : loaded_so_far)
    if (other.loaded && other.name == status.name)
      return close_and_refuse(fmt::format("duplicate plugin name: a plugin named {} is already loaded from {}",
                                          subdiv::quoted(status.name), escaped(other.file)));
  // The plugin's own code runs from here on. Whatever it staged is dropped before the
  // library is closed; a refused plugin's registrations are undone by commit().
  std::string reason;
  {
    PluginRegistry registry(status.name, file.string());
    try {
      info->register_plugin(registry);
    } catch (const std::exception& e) {
      reason = fmt::format("its registration threw: {}", e.what());
    } catch (...) {
      reason = "its registration threw an exception";
    }
    if (reason.empty()) {
      try {
        status.provides = registry.commit();
      } catch (const std::exception& e) {
        reason = e.what();
      } catch (...) {
        reason = "registering its contents threw an exception";
      }
    }
  }
  if (!reason.empty()) {
    status.provides.clear();
    return close_and_refuse(reason);
  }
  status.loaded = true;
  return handle;
}

std::vector<std::string> split_path_list(const std::string& list) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= list.size()) {
    size_t end = list.find(':', start);
    if (end == std::string::npos) end = list.size();
    if (end > start) out.push_back(list.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

std::vector<fs::path> libraries_in(const fs::path& dir) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && entry.path().extension() == kLibrarySuffix) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

unsigned plugin_interface_version() { return SUBDIV_PLUGIN_INTERFACE_VERSION; }

PluginStatus load_plugin(const fs::path& file, const std::string& found_by) {
  LoaderState& s = state();
  std::lock_guard lock(s.mutex);
  PluginStatus status;
  status.file = file.string();
  status.found_by = found_by;
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file, ec);
  s.tried.insert(ec ? file.string() : canonical.string());
  if (void* handle = try_load(file, status, s.statuses)) s.handles.push_back(handle);
  s.statuses.push_back(status);
  return status;
}

std::vector<PluginStatus> load_plugins(const PluginSearch& search) {
  std::vector<std::pair<fs::path, std::string>> files;  // file, found_by
  std::error_code ec;
  for (const auto& p : search.paths) {
    // Only a file named with --plugin is the user's explicit request (refused loudly by the
    // front-ends); a broken library among a folder's is warned about and skipped.
    if (fs::is_directory(p, ec))
      for (const auto& f : libraries_in(p)) files.emplace_back(f, "--plugin folder");
    else
      files.emplace_back(p, "--plugin");
  }
  if (search.environment)
    if (const char* env = std::getenv("SUBDIV_PLUGIN_PATH"))
      for (const auto& entry : split_path_list(env)) {
        if (fs::is_directory(entry, ec))
          for (const auto& f : libraries_in(entry)) files.emplace_back(f, "SUBDIV_PLUGIN_PATH");
        else if (fs::exists(entry, ec))
          files.emplace_back(entry, "SUBDIV_PLUGIN_PATH");
      }
  const char* no_installed = std::getenv("SUBDIV_NO_INSTALLED_PLUGINS");
  if (search.installed && !(no_installed && std::string(no_installed) == "1"))
    for (const auto& dir : installed_plugin_dirs())
      for (const auto& f : libraries_in(dir)) files.emplace_back(f, "installed plugin folder");

  std::vector<PluginStatus> out;
  for (const auto& [file, found_by] : files) {
    const fs::path canonical = fs::weakly_canonical(file, ec);
    {
      LoaderState& s = state();
      std::lock_guard lock(s.mutex);
      if (s.tried.count(ec ? file.string() : canonical.string())) continue;
    }
    out.push_back(load_plugin(file, found_by));
  }
  return out;
}

std::vector<PluginStatus> plugin_statuses() {
  LoaderState& s = state();
  std::lock_guard lock(s.mutex);
  return s.statuses;
}

std::vector<fs::path> installed_plugin_dirs() {
  std::vector<fs::path> dirs;
  if (const fs::path lib = library_directory(); !lib.empty()) dirs.push_back(lib / "subdivkit" / "plugins");
  const fs::path configured = SUBDIV_PLUGIN_DIR_INSTALL;
  if (std::find(dirs.begin(), dirs.end(), configured) == dirs.end()) dirs.push_back(configured);
  return dirs;
}

}  // namespace subdiv
