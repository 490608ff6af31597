#include "framework/io/formats.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace subdiv {
namespace {

constexpr std::array<std::string_view, 7> kInputs = {".obj", ".off", ".ply", ".stl",
                                                     ".om",  ".vtp", ".vtk"};
constexpr std::array<std::string_view, 6> kOutputs = {".obj", ".off", ".ply",
                                                      ".stl", ".vtp", ".pvd"};

template <size_t N>
bool contains(const std::array<std::string_view, N>& list, const std::string& ext) {
  return std::find(list.begin(), list.end(), ext) != list.end();
}

}  // namespace

std::string lowercase_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

bool is_supported_input(const std::filesystem::path& file) {
  return contains(kInputs, lowercase_extension(file));
}

bool is_supported_output(const std::filesystem::path& file) {
  return contains(kOutputs, lowercase_extension(file));
}

bool is_vtk_output(const std::filesystem::path& file) {
  const std::string ext = lowercase_extension(file);
  return ext == ".vtp" || ext == ".pvd";
}

std::string supported_input_formats() { return fmt::format("{}", fmt::join(kInputs, ", ")); }
std::string supported_output_formats() { return fmt::format("{}", fmt::join(kOutputs, ", ")); }

}  // namespace subdiv
