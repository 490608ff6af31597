#include "framework/util/quoted_text.h"

#include <fmt/format.h>

namespace subdiv {
namespace {

// The length of the valid UTF-8 sequence at text[i] (1 to 4), or 0 when it is not one
// (a stray continuation byte, an overlong form, a surrogate, past U+10FFFF, cut short).
std::size_t utf8_length(std::string_view text, std::size_t i, char32_t& code) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
  const unsigned char lead = b(0);
  std::size_t n = lead < 0x80             ? 1
                  : (lead & 0xE0) == 0xC0 ? 2
                  : (lead & 0xF0) == 0xE0 ? 3
                  : (lead & 0xF8) == 0xF0 ? 4
                                          : 0;
  if (n == 0 || i + n > text.size()) return 0;
  code = n == 1 ? lead : n == 2 ? lead & 0x1F : n == 3 ? lead & 0x0F : lead & 0x07;
  for (std::size_t k = 1; k < n; ++k) {
    if ((b(k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (b(k) & 0x3F);
  }
  static constexpr char32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < kSmallest[n] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return n;
}

std::string escape(std::string_view text, bool keep_layout) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    char32_t code = 0;
    const std::size_t n = utf8_length(text, i, code);
    const auto byte = static_cast<unsigned char>(text[i]);
    if (n == 0) {  // not UTF-8: the byte itself
      out += fmt::format("\\x{:02x}", unsigned(byte));
      ++i;
      continue;
    }
    const bool control = code < 0x20 || code == 0x7F || (code >= 0x80 && code <= 0x9F);
    if (keep_layout && (code == '\n' || code == '\t'))
      out += char(code);
    else if (code == '\n')
      out += "\\n";
    else if (code == '\t')
      out += "\\t";
    else if (code == '\r')
      out += "\\r";
    else if (control && n == 1)
      out += fmt::format("\\x{:02x}", unsigned(byte));
    else if (control)
      out += fmt::format("\\u{:04x}", unsigned(code));
    else
      out.append(text.substr(i, n));
    i += n;
  }
  return out;
}

}  // namespace

std::string escaped(std::string_view text) { return escape(text, false); }

std::string quoted(std::string_view text) {
  std::string out(1, '\'');  // appended, not "'" + ...: GCC 12 warns falsely (-Wrestrict) on that
  out += escape(text, false);
  out += '\'';
  return out;
}

std::string terminal_safe(std::string_view message) { return escape(message, true); }

}  // namespace subdiv
