#include "framework/util/checked_file_stream.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

std::string write_failure_text(const std::string& shown, int error) {
  if (error == ENOSPC || error == EDQUOT || error == EFBIG)
    return fmt::format("cannot write {}: the disk is full or the file is larger than allowed ({}); free some space "
                       "or write to another disk",
                       subdiv::quoted(shown), std::strerror(error));
  return fmt::format("cannot write {}: writing failed ({})", subdiv::quoted(shown), std::strerror(error));
}

CheckedFileBuffer::CheckedFileBuffer(const std::filesystem::path& file, const std::filesystem::path& shown)
    : fd_(::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666)),
      shown_(shown.string()),
      buffer_(new char[kBufferSize]) {
  if (fd_ < 0)
    throw Error(fmt::format("cannot write {}: cannot create the file ({})", subdiv::quoted(shown_), std::strerror(errno)));
  setp(buffer_.get(), buffer_.get() + kBufferSize);
}

CheckedFileBuffer::~CheckedFileBuffer() {
  if (fd_ >= 0) ::close(fd_);
}

void CheckedFileBuffer::put_bytes(const char* data, std::size_t count) {
  while (count > 0 && error_ == 0) {
    const ssize_t written = ::pwrite(fd_, data, count, off_t(position_));
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      error_ = written < 0 ? errno : ENOSPC;
      break;
    }
    data += written, count -= std::size_t(written), position_ += written;
  }
  position_ += (long long)count;  // dropped after an error, but counted: positions stay right
  end_ = std::max(end_, position_);
}

void CheckedFileBuffer::flush_buffer() {
  put_bytes(pbase(), std::size_t(pptr() - pbase()));
  setp(buffer_.get(), buffer_.get() + kBufferSize);
}

CheckedFileBuffer::int_type CheckedFileBuffer::overflow(int_type c) {
  flush_buffer();
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

std::streamsize CheckedFileBuffer::xsputn(const char* data, std::streamsize count) {
  if (count <= epptr() - pptr()) {
    std::memcpy(pptr(), data, std::size_t(count));
    pbump(int(count));
    return count;
  }
  flush_buffer();
  put_bytes(data, std::size_t(count));  // large writes go straight to the file
  return count;
}

int CheckedFileBuffer::sync() {
  flush_buffer();
  return 0;  // never a failure towards the stream's user: close() reports it
}

CheckedFileBuffer::pos_type CheckedFileBuffer::seekoff(off_type off, std::ios_base::seekdir dir,
                                                       std::ios_base::openmode) {
  flush_buffer();
  const long long base = dir == std::ios_base::beg ? 0 : dir == std::ios_base::cur ? position_ : end_;
  if (base + off < 0) return pos_type(off_type(-1));
  position_ = base + off;
  return pos_type(off_type(position_));
}

CheckedFileBuffer::pos_type CheckedFileBuffer::seekpos(pos_type pos, std::ios_base::openmode which) {
  return seekoff(off_type(pos), std::ios_base::beg, which);
}

void CheckedFileBuffer::close() {
  if (fd_ < 0) return;
  flush_buffer();
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 && error_ == 0) error_ = errno;
  if (error_ != 0) throw Error(write_failure_text(shown_, error_));
}

CheckedFileStream::CheckedFileStream(const std::filesystem::path& file, const std::filesystem::path& shown)
    : std::ostream(nullptr), buffer_(file, shown) {
  rdbuf(&buffer_);
}

}  // namespace subdiv
