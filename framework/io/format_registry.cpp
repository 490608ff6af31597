#include "framework/io/format_registry.h"

#include <algorithm>
#include <mutex>
#include <utility>

namespace subdiv {
namespace {

template <class Function>
struct Registry {
  std::mutex mutex;
  std::vector<std::pair<std::string, Function>> entries;  // few: a list is enough

  void add(std::string extension, Function f) {
    std::lock_guard lock(mutex);
    for (auto& [ext, fn] : entries)
      if (ext == extension) return void(fn = std::move(f));
    entries.emplace_back(std::move(extension), std::move(f));
  }
  // Entries are never removed, so a pointer stays valid once handed out.
  const Function* find(std::string_view extension) {
    std::lock_guard lock(mutex);
    for (const auto& [ext, fn] : entries)
      if (ext == extension) return &fn;
    return nullptr;
  }
  std::vector<std::string> extensions() {
    std::lock_guard lock(mutex);
    std::vector<std::string> out;
    for (const auto& entry : entries) out.push_back(entry.first);
    return out;
  }
};

Registry<MeshFileReader>& readers() {
  static Registry<MeshFileReader> r;
  return r;
}
Registry<MeshFileWriter>& writers() {
  static Registry<MeshFileWriter> w;
  return w;
}

}  // namespace

void register_mesh_reader(std::string extension, MeshFileReader reader) {
  readers().add(std::move(extension), std::move(reader));
}
void register_mesh_writer(std::string extension, MeshFileWriter writer) {
  writers().add(std::move(extension), std::move(writer));
}
const MeshFileReader* registered_mesh_reader(std::string_view extension) { return readers().find(extension); }
const MeshFileWriter* registered_mesh_writer(std::string_view extension) { return writers().find(extension); }
std::vector<std::string> registered_input_extensions() { return readers().extensions(); }
std::vector<std::string> registered_output_extensions() { return writers().extensions(); }

}  // namespace subdiv
