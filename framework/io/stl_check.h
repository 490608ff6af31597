#pragma once
// STL files checked before OpenMesh reads them. OpenMesh's STL reader takes "nan" as a
// coordinate without a word, reads a broken ASCII file as "no faces", and names no line;
// this check walks the file first and names the line and the fix. Internal to io/.
#include <filesystem>
#include <string_view>

namespace subdiv::io_detail {

// Throws subdiv::Error "<file>:<line>: ..." for ASCII STL, "<file>: triangle i ..." for
// binary STL, or "<file>: ..." when the file is neither.
void check_stl_text(const std::filesystem::path& file, std::string_view bytes);
void check_stl_file(const std::filesystem::path& file);

}  // namespace subdiv::io_detail
