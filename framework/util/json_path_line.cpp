#include "framework/util/json_path_line.h"

#include <cctype>
#include <optional>
#include <vector>

namespace subdiv {
namespace {

struct Step {
  std::string key;   // an object key, or
  long index = -1;   // an array index
};

// "a.b[2].c" -> a, b, [2], c. Anything else (spaces, empty keys) is no path.
std::optional<std::vector<Step>> parse_path(std::string_view path) {
  std::vector<Step> steps;
  size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {
      const size_t close = path.find(']', i);
      if (close == std::string_view::npos || close == i + 1) return std::nullopt;
      long v = 0;
      for (size_t d = i + 1; d < close; ++d) {
        if (!std::isdigit(static_cast<unsigned char>(path[d])) || v > 1'000'000) return std::nullopt;
        v = 10 * v + (path[d] - '0');
      }
      steps.push_back({"", v});
      i = close + 1;
      if (i < path.size() && path[i] == '.') ++i;
      continue;
    }
    size_t end = i;
    while (end < path.size() && path[end] != '.' && path[end] != '[') ++end;
    const std::string_view key = path.substr(i, end - i);
    if (key.empty() || key.find(' ') != std::string_view::npos) return std::nullopt;
    steps.push_back({std::string(key), -1});
    i = end < path.size() && path[end] == '.' ? end + 1 : end;
  }
  return steps;
}

class Walker {
public:
  explicit Walker(std::string_view text) : t_(text) {}

  // Position of the value at `steps`, or npos.
  size_t find(const std::vector<Step>& steps) {
    space();
    for (const Step& s : steps) {
      if (at_end()) return npos;
      if (s.index >= 0 ? !enter_element(s.index) : !enter_member(s.key)) return npos;
    }
    return at_end() ? npos : p_;
  }

  static constexpr size_t npos = std::string_view::npos;

private:
  bool at_end() const { return p_ >= t_.size(); }
  void space() {
    while (!at_end() && std::isspace(static_cast<unsigned char>(t_[p_]))) ++p_;
  }
  // A string at p_ (the opening quote); returns its raw text between the quotes.
  std::string_view string() {
    const size_t start = ++p_;
    while (!at_end() && t_[p_] != '"') p_ += t_[p_] == '\\' ? 2 : 1;
    if (at_end()) return {};
    return t_.substr(start, p_++ - start);
  }
  // Skips one value of any kind.
  void skip() {
    int depth = 0;
    do {
      if (at_end()) return;
      const char c = t_[p_];
      if (c == '"') string();
      else {
        if (c == '{' || c == '[') ++depth;
        else if (c == '}' || c == ']') --depth;
        ++p_;
      }
      if (depth > 0) continue;
      if (c != '"' && c != '{' && c != '[' && c != '}' && c != ']')  // a scalar: read to its end
        while (!at_end() && t_[p_] != ',' && t_[p_] != '}' && t_[p_] != ']' &&
               !std::isspace(static_cast<unsigned char>(t_[p_])))
          ++p_;
    } while (depth > 0);
  }
  bool enter_member(const std::string& key) {
    if (t_[p_] != '{') return false;
    ++p_;
    for (space(); !at_end() && t_[p_] == '"'; space()) {
      const std::string_view k = string();
      space();
      if (at_end() || t_[p_] != ':') return false;
      ++p_;
      space();
      if (k == key) return true;
      skip();
      space();
      if (!at_end() && t_[p_] == ',') ++p_;
    }
    return false;
  }
  bool enter_element(long index) {
    if (t_[p_] != '[') return false;
    ++p_;
    space();
    for (long i = 0; !at_end() && t_[p_] != ']'; ++i) {
      if (i == index) return true;
      skip();
      space();
      if (!at_end() && t_[p_] == ',') ++p_;
      space();
    }
    return false;
  }

  std::string_view t_;
  size_t p_ = 0;
};

}  // namespace

int json_path_line(std::string_view text, std::string_view path) {
  const auto steps = parse_path(path);
  if (!steps) return 0;
  const size_t at = Walker(text).find(*steps);
  if (at == Walker::npos) return 0;
  int line = 1;
  for (size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return line;
}

std::string with_json_line(const std::string& message, const std::string& label, std::string_view text) {
  const std::string prefix = label + ": ";
  if (message.compare(0, prefix.size(), prefix) != 0) return message;
  const size_t end = message.find(": ", prefix.size());
  if (end == std::string::npos) return message;
  const int line = json_path_line(text, std::string_view(message).substr(prefix.size(), end - prefix.size()));
  if (line == 0) return message;
  return label + ":" + std::to_string(line) + ": " + message.substr(prefix.size());
}

}  // namespace subdiv
