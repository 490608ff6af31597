#include "framework/io/formats.h"

#include <algorithm>
#include <vector>
#include <cctype>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "framework/io/format_registry.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

// What io/ reads and writes itself; more come from format_registry.h (VTK's).
const std::vector<std::string> kBuiltInInputs = {".obj", ".off", ".ply", ".stl", ".om"};
const std::vector<std::string> kBuiltInOutputs = {".obj", ".off", ".ply", ".stl"};
// Formats of SubdivKit's VTK file IO, named in the message when it is not linked in.
const std::vector<std::string> kVtkFormats = {".vtp", ".vtk", ".pvd"};

bool contains(const std::vector<std::string>& list, const std::string& ext) {
  return std::find(list.begin(), list.end(), ext) != list.end();
}

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  for (const auto& x : b)
    if (!contains(a, x)) a.push_back(x);
  return a;
}

std::vector<std::string> inputs() { return joined(kBuiltInInputs, registered_input_extensions()); }
std::vector<std::string> outputs() { return joined(kBuiltInOutputs, registered_output_extensions()); }

}  // namespace

std::string lowercase_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

bool is_supported_input(const std::filesystem::path& file) { return contains(inputs(), lowercase_extension(file)); }

bool is_supported_output(const std::filesystem::path& file) { return contains(outputs(), lowercase_extension(file)); }

std::string unsupported_format_hint(const std::filesystem::path& file) {
  const std::string ext = lowercase_extension(file);
  if (!contains(kVtkFormats, ext)) return "";
  // Registered VTK IO reads .vtp and .vtk; a .pvd is an index of level files, not a mesh.
  if (ext == ".pvd" && contains(registered_input_extensions(), ".vtp"))
    return fmt::format("; a .pvd is ParaView's index of level files, not a mesh: read one of them instead, e.g. "
                       "{}",
                       subdiv::quoted((file.parent_path() / (file.stem().string() + "_levels") / "level_0.vtp").string()));
  return "; VTK formats need SubdivKit's VTK file IO, which this program was built without (link SubdivKit::vtkio "
         "and call register_vtk_formats())";
}

bool is_vtk_output(const std::filesystem::path& file) {
  const std::string ext = lowercase_extension(file);
  return ext == ".vtp" || ext == ".pvd";
}

std::string supported_input_formats() { return fmt::format("{}", fmt::join(inputs(), ", ")); }
std::string supported_output_formats() { return fmt::format("{}", fmt::join(outputs(), ", ")); }

}  // namespace subdiv
