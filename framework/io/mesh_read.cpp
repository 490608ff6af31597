#include "framework/io/mesh_read.h"

#include <fmt/format.h>

#include "framework/io/format_registry.h"
#include "framework/io/formats.h"
#include "framework/io/io_progress.h"
#include "framework/io/mesh_validate.h"
#include "framework/io/readers.h"
#include "framework/util/error.h"
#include "framework/util/input_errors.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

MeshData read_mesh(const std::filesystem::path& file, const std::function<void(double done)>& progress) {
  const std::string ext = lowercase_extension(file);
  if (!is_supported_input(file))
    throw Error(fmt::format("cannot read {}: unknown mesh format {}; supported: {}{}",
                            subdiv::quoted(file.string()), subdiv::quoted(ext.empty() ? "(no extension)" : ext),
                            supported_input_formats(), unsupported_format_hint(file)));
  const MeshFileReader* registered = registered_mesh_reader(ext);
  std::error_code size_error;
  const auto bytes = std::filesystem::file_size(file, size_error);
  const io_detail::ReadProgressScope reading(progress, size_error ? 0 : std::size_t(bytes));
  return naming_file_on_failure(file.string(), [&] {
    MeshData mesh = registered        ? (*registered)(file)
                    : ext == ".obj"   ? io_detail::read_obj(file)
                    : ext == ".off"   ? io_detail::read_off(file)
                    : ext == ".ply"   ? io_detail::read_ply(file)
                                      : io_detail::read_with_openmesh(file);
    // The text readers already check with line numbers; this catches the rest (registered
    // formats' and OpenMesh data) with the same rules.
    validate_mesh_data(mesh, file.string());
    return mesh;
  });
}

}  // namespace subdiv
