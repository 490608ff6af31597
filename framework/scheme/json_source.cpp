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
    throw Error(json_syntax_error(text, label, e.byte, e.what()));
  } catch (const nlohmann::json::exception& e) {  // anything check_json_text did not foresee
    throw Error(fmt::format("{}: JSON the parser refuses: {}", label, e.what()));
  }
}

}  // namespace subdiv
