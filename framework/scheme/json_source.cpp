#include "framework/scheme/json_source.h"

#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "framework/util/error.h"

namespace subdiv {

nlohmann::ordered_json read_json_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot open scheme file '{}': no such file or not readable", path.string()));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_json_text(buffer.str(), path.string());
}

nlohmann::ordered_json parse_json_text(const std::string& text, const std::string& label) {
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // Turn the byte offset into line:column so editors can jump there.
    size_t line = 1, column = 1;
    for (size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') ++line, column = 1;
      else ++column;
    }
    std::string what = e.what();
    if (auto pos = what.find("parse error"); pos != std::string::npos) what = what.substr(pos);
    throw Error(fmt::format("{}:{}:{}: malformed JSON: {}", label, line, column, what));
  }
}

}  // namespace subdiv
