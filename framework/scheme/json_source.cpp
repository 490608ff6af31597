#include "framework/scheme/json_source.h"

#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "framework/util/error.h"
#include "framework/util/input_file.h"
#include "framework/util/json_text_check.h"

namespace subdiv {

// The largest built-in scheme is a few kilobytes; a scheme file of megabytes is a mistake
// (or an attack on the parser's time and memory).
constexpr std::uintmax_t kMaxSchemeFileBytes = 4'000'000;

std::string read_scheme_text(const std::filesystem::path& path) {
  return read_input_file(path, "scheme", kMaxSchemeFileBytes);
}

nlohmann::ordered_json read_json_file(const std::filesystem::path& path) {
  return parse_json_text(read_scheme_text(path), path.string());
}

nlohmann::ordered_json parse_json_text(const std::string& text, const std::string& label) {
  check_json_text(text, label);  // depth and number range, with their places
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
  } catch (const nlohmann::json::exception& e) {  // anything check_json_text did not foresee
    throw Error(fmt::format("{}: JSON the parser refuses: {}", label, e.what()));
  }
}

}  // namespace subdiv
