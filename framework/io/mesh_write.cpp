#include "framework/io/mesh_write.h"

#include <fmt/format.h>

#include "framework/io/formats.h"
#include "framework/io/mesh_validate.h"
#include "framework/io/format_registry.h"
#include "framework/io/writers.h"
#include "framework/util/atomic_file.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace fs = std::filesystem;

void check_mesh_output_format(const fs::path& file) {
  if (is_supported_output(file)) return;
  const std::string ext = lowercase_extension(file);
  throw Error(fmt::format("cannot write {}: unknown mesh format {}; supported: {}{}", subdiv::quoted(file.string()),
                          subdiv::quoted(ext.empty() ? "(no extension)" : ext), supported_output_formats(),
                          unsupported_format_hint(file)));
}

void write_mesh(const fs::path& file, const MeshData& mesh, const std::function<void(double done)>& progress) {
  check_mesh_output_format(file);
  const std::string ext = lowercase_extension(file);
  if (const MeshFileWriter* registered = registered_mesh_writer(ext)) return (*registered)(file, mesh);
  validate_mesh_data(mesh, fmt::format("cannot write {}", subdiv::quoted(file.string())));
  const auto writer = ext == ".obj"   ? io_detail::write_obj
                      : ext == ".off" ? io_detail::write_off
                      : ext == ".ply" ? io_detail::write_ply
                                      : io_detail::write_stl;
  write_file_atomically(file, [&](const fs::path& tmp) { writer(tmp, file, mesh, progress); });
}

}  // namespace subdiv
