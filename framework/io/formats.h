#pragma once
// Which file formats io/ reads and writes, for dispatch and for help texts.
#include <filesystem>
#include <string>

namespace subdiv {

// The extension of `file`, lower case, with its dot (".obj"); empty if it has none.
std::string lowercase_extension(const std::filesystem::path& file);

// Built-in formats and those registered (io/format_registry.h: VTK's, once
// register_vtk_formats() ran).
bool is_supported_input(const std::filesystem::path& file);   // read_mesh accepts it
bool is_supported_output(const std::filesystem::path& file);  // write_mesh or write_pvd accept it
// For an unsupported file: why, if a library this program lacks would read it ("" else).
std::string unsupported_format_hint(const std::filesystem::path& file);
bool is_vtk_output(const std::filesystem::path& file);        // .vtp or .pvd: ParaView output

// Comma-separated lists for help texts and error messages, e.g. ".obj, .off, ...".
std::string supported_input_formats();
std::string supported_output_formats();

}  // namespace subdiv
