#include "framework/util/buffered_output.h"

#include <cerrno>
#include <cstring>

#include "framework/util/checked_file_stream.h"
#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

BufferedOutput::BufferedOutput(const std::filesystem::path& file,
                               const std::filesystem::path& shown)
    : file_(std::fopen(file.c_str(), "wb")), shown_(shown.string()) {
  if (!file_) fail("cannot create the file");
}

BufferedOutput::~BufferedOutput() {
  if (file_) std::fclose(file_);
}

void BufferedOutput::write(const void* bytes, std::size_t count) {
  const char* p = static_cast<const char*>(bytes);
  buffer_.append(p, p + count);
  if (buffer_.size() >= kFlushSize) flush();
}

void BufferedOutput::flush() {
  if (buffer_.size() != 0 && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size())
    fail("writing failed");
  buffer_.clear();
}

void BufferedOutput::close() {
  flush();
  std::FILE* f = file_;
  file_ = nullptr;
  if (std::fclose(f) != 0) fail("closing failed");
}

void BufferedOutput::fail(std::string_view what) {
  const int error = errno;
  if (error == ENOSPC || error == EDQUOT || error == EFBIG) throw Error(write_failure_text(shown_, error));
  throw Error(fmt::format("cannot write {}: {} ({})", subdiv::quoted(shown_), what, std::strerror(error)));
}

}  // namespace subdiv
