// User text in messages (framework/util/quoted_text.h): no byte of it may drive a terminal
// (ESC and the one-byte CSI 0x9B start escape sequences in ECMA-48) or end a C string (NUL);
// valid UTF-8 stays readable.
#include <doctest/doctest.h>

#include <string>

#include "framework/util/quoted_text.h"

using namespace subdiv;
using namespace std::string_literals;

namespace {
bool has_raw_control(const std::string& s, bool allow_layout) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto b = static_cast<unsigned char>(s[i]);
    if (allow_layout && (b == '\n' || b == '\t')) continue;
    if (b < 0x20 || b == 0x7F) return true;
    if (b == 0xC2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) <= 0x9F) return true;  // C1 as UTF-8
    if (b == 0x9B && (i == 0 || static_cast<unsigned char>(s[i - 1]) < 0xC0)) return true;  // a raw CSI byte
  }
  return false;
}
}  // namespace

TEST_CASE("escaped: control bytes, DEL, NUL and terminal escapes are shown as \\xNN") {
  CHECK(escaped("a\x1b[2Jb") == "a\\x1b[2Jb");
  CHECK(escaped("line\nnext\ttab\rcr") == "line\\nnext\\ttab\\rcr");
  CHECK(escaped("nul\0end"s) == "nul\\x00end");
  CHECK(escaped("del\x7f") == "del\\x7f");
  CHECK(quoted("x\x07y") == "'x\\x07y'");
}

TEST_CASE("escaped: valid UTF-8 stays, C1 controls and invalid bytes are escaped") {
  CHECK(escaped("naïve 網格 ∂") == "naïve 網格 ∂");
  CHECK(escaped("\xc2\x9b" "31m") == "\\u009b31m");       // CSI as a code point
  CHECK(escaped("\x9b" "31m") == "\\x9b31m");             // CSI as a raw byte (not UTF-8)
  CHECK(escaped("\xff\xfe") == "\\xff\\xfe");
  CHECK(escaped("\xc3") == "\\xc3");                       // cut short
  CHECK(escaped("\xc0\xaf") == "\\xc0\\xaf");             // overlong '/'
  CHECK(escaped("\xed\xa0\x80") == "\\xed\\xa0\\x80");    // a UTF-16 surrogate
  CHECK(escaped("\xf4\x90\x80\x80") == "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
}

TEST_CASE("escaping twice changes nothing (a front-end escapes messages whose names are escaped already)") {
  for (const std::string text : {"a\x1b[2J", "x\ny\xff\xc2\x9b", "plain \\ text"}) {
    CAPTURE(text);
    CHECK(escaped(escaped(text)) == escaped(text));
    CHECK(terminal_safe(escaped(text)) == escaped(text));
  }
}

TEST_CASE("terminal_safe keeps a message's line breaks and tabs, escapes the rest; no output has a raw control") {
  CHECK(terminal_safe("error:\n  file\x1b]0;title\x07") == "error:\n  file\\x1b]0;title\\x07");
  // Every byte value in every position: nothing that drives a terminal survives.
  for (int b = 0; b < 256; ++b) {
    const std::string text = "a" + std::string(1, char(b)) + "\x1b" + std::string(1, char(b)) + "z";
    CAPTURE(b);
    CHECK_FALSE(has_raw_control(escaped(text), false));
    CHECK_FALSE(has_raw_control(terminal_safe(text), true));
    CHECK(escaped(text).find('\0') == std::string::npos);
  }
}
