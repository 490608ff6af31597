#pragma once
// Reading a JSON file with messages that name the file and, for syntax errors, the line
// and column.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace subdiv {

nlohmann::ordered_json read_json_file(const std::filesystem::path& path);

}  // namespace subdiv
