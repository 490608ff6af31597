#pragma once
// Everything `subdiv` prints for people goes through print_safe: file, scheme, array and
// plugin names in it are user text, and a control byte in one (an ESC sequence in a file
// name) would otherwise reach the terminal raw. terminal_safe keeps line breaks and tabs
// and escapes the rest (framework/util/quoted_text.h); escaping twice changes nothing.
#include <cstdio>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "framework/util/quoted_text.h"

namespace subdiv::cli {

template <typename... Args>
void print_safe(std::FILE* to, fmt::format_string<Args...> format, Args&&... args) {
  const std::string text = terminal_safe(fmt::format(format, std::forward<Args>(args)...));
  std::fwrite(text.data(), 1, text.size(), to);
}

template <typename... Args>
void print_safe(fmt::format_string<Args...> format, Args&&... args) {
  print_safe(stdout, format, std::forward<Args>(args)...);
}

}  // namespace subdiv::cli
