#include "framework/io/vtk/vtk_xml_text.h"

#include <fmt/format.h>

#include "framework/util/error.h"
#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv::io_detail {

std::string xml_attribute_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\t': out += "&#9;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

// The length of the UTF-8 sequence at `at`, or 0 if it is not one (overlong forms and
// surrogates included, as XML parsers refuse them).
std::size_t utf8_length(std::string_view s, std::size_t at) {
  const auto byte = [&](std::size_t i) { return i < s.size() ? static_cast<unsigned char>(s[i]) : 0u; };
  const unsigned b0 = byte(at);
  const auto cont = [&](std::size_t i) { return (byte(i) & 0xC0) == 0x80; };
  if (b0 < 0x80) return 1;
  if (b0 >= 0xC2 && b0 <= 0xDF) return cont(at + 1) ? 2 : 0;
  if (b0 >= 0xE0 && b0 <= 0xEF) {
    const unsigned b1 = byte(at + 1);
    if ((b0 == 0xE0 && b1 < 0xA0) || (b0 == 0xED && b1 >= 0xA0)) return 0;
    return cont(at + 1) && cont(at + 2) ? 3 : 0;
  }
  if (b0 >= 0xF0 && b0 <= 0xF4) {
    const unsigned b1 = byte(at + 1);
    if ((b0 == 0xF0 && b1 < 0x90) || (b0 == 0xF4 && b1 >= 0x90)) return 0;
    return cont(at + 1) && cont(at + 2) && cont(at + 3) ? 4 : 0;
  }
  return 0;
}

}  // namespace

void require_xml_text(std::string_view text, std::string_view what, std::string_view context) {
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r')
      throw Error(fmt::format("{}: {} {} holds the control character 0x{:02x} at byte {}, which XML (and so VTK's "
                              "file formats) cannot hold; rename it",
                              context, what, subdiv::quoted(shortened(text)), unsigned(c), i));
    const std::size_t n = utf8_length(text, i);
    if (n == 0)
      throw Error(fmt::format("{}: {} {} is not UTF-8 text (byte 0x{:02x} at {}), which VTK's XML files need; "
                              "rename it",
                              context, what, subdiv::quoted(shortened(text)), unsigned(c), i));
    i += n;
  }
}

}  // namespace subdiv::io_detail
