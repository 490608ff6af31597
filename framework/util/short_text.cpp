#include "framework/util/short_text.h"

#include <fmt/format.h>

namespace subdiv {

std::string shortened(std::string_view text, std::size_t max_chars) {
  const bool cut = text.size() > max_chars;
  std::string out(cut ? text.substr(0, max_chars) : text);
  // Do not end inside a UTF-8 sequence: drop continuation bytes and their lead byte.
  if (cut) {
    while (!out.empty() && (static_cast<unsigned char>(out.back()) & 0xC0) == 0x80) out.pop_back();
    if (!out.empty() && static_cast<unsigned char>(out.back()) >= 0xC0) out.pop_back();
  }
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = ' ';
  if (cut) out += fmt::format("... ({} characters)", text.size());
  return out;
}

}  // namespace subdiv
