#pragma once
// Scheme JSON written by tests into a folder of their own under the temporary directory, for
// the loader, the validator and the engine to read back.
#include <filesystem>
#include <fstream>
#include <string>

namespace subdiv::test {

inline std::filesystem::path write_scheme_file(const std::string& folder, const std::string& name,
                                               const std::string& text) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / folder;
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / (name + ".json");
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

}  // namespace subdiv::test
