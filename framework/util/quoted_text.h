#pragma once
// User text in messages, made safe to print: file names, array names and scheme or JSON
// strings may hold control bytes, terminal escape sequences (ESC [ ... or the one-byte CSI
// 0x9B, which a terminal then runs: a hostile file name could move the cursor, rewrite
// earlier lines or retitle the window), invalid UTF-8 or a NUL (which ends a C string, so a
// message would stop there). Such bytes are shown as \xNN (\n, \r and \t as themselves,
// escaped); valid UTF-8 text, accents and CJK included, stays as it is.
#include <string>
#include <string_view>

namespace subdiv {

// `text` with every control byte, C1 control (U+0080..U+009F), DEL and byte of invalid UTF-8
// written as an escape. Backslashes stay as they are, so escaping twice changes nothing
// (a front-end's terminal_safe over a message whose names were escaped already).
std::string escaped(std::string_view text);
// escaped(text) between single quotes, the way messages quote names: 'a\x1bb'.
std::string quoted(std::string_view text);
// A whole message for the terminal: as escaped(), but its line breaks and tabs kept (they
// are the message's layout). Front-ends pass every message through it before printing.
std::string terminal_safe(std::string_view message);

}  // namespace subdiv
