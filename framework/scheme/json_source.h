#pragma once
// Reading a JSON file with messages that name the file and, for syntax errors, the line
// and column.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace subdiv {

nlohmann::ordered_json read_json_file(const std::filesystem::path& path);
// The text of a scheme file, with the size limit read_json_file applies.
std::string read_scheme_text(const std::filesystem::path& path);
// The same for JSON text (schemes that plugins carry); `label` stands for the file name.
nlohmann::ordered_json parse_json_text(const std::string& text, const std::string& label);

}  // namespace subdiv
