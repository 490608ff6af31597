#pragma once
// A binary output file with a large buffer and checked errors: every write failure
// (full disk, closed pipe) surfaces as subdiv::Error from write() or close() instead of
// a silently truncated file. Text goes through fmt, which is locale-independent and
// prints doubles in their shortest round-trip form.
#include <cstdio>
#include <iterator>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

namespace subdiv {

class BufferedOutput {
public:
  // `shown` is the name used in messages: the final target, not the temporary file.
  BufferedOutput(const std::filesystem::path& file, const std::filesystem::path& shown);
  BufferedOutput(const BufferedOutput&) = delete;
  BufferedOutput& operator=(const BufferedOutput&) = delete;
  ~BufferedOutput();  // closes without checking; call close() to learn about failures

  template <typename... Args>
  void print(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(std::back_inserter(buffer_), format, std::forward<Args>(args)...);
    if (buffer_.size() >= kFlushSize) flush();
  }
  void write(const void* bytes, std::size_t count);
  void close();

private:
  static constexpr std::size_t kFlushSize = 1 << 20;
  void flush();
  [[noreturn]] void fail(std::string_view what);

  std::FILE* file_ = nullptr;
  std::string shown_;
  fmt::memory_buffer buffer_;
};

}  // namespace subdiv
