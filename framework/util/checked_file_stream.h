#pragma once
// An output stream for writers that cannot be trusted with a failing stream (VTK's XML
// writer crashes when its ofstream fails on a full disk: it reads back positions of a
// stream in a failed state). This stream never fails towards its user: the first write
// error is remembered, every later byte is dropped while positions still advance, and
// close() reports the error as subdiv::Error naming the target. Seeking is supported
// (VTK's appended mode goes back to fill in offsets): writes go to the file with pwrite at
// the stream's own position.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <streambuf>

namespace subdiv {

// "cannot write '<shown>': ..." for the errno of a failed write; a full disk (or a file size
// limit) says so and how to go on.
std::string write_failure_text(const std::string& shown, int error);

class CheckedFileBuffer : public std::streambuf {
public:
  // Creates (or truncates) `file`; `shown` names it in messages (the target, not the
  // temporary). Throws subdiv::Error if the file cannot be created.
  CheckedFileBuffer(const std::filesystem::path& file, const std::filesystem::path& shown);
  CheckedFileBuffer(const CheckedFileBuffer&) = delete;
  CheckedFileBuffer& operator=(const CheckedFileBuffer&) = delete;
  ~CheckedFileBuffer() override;  // closes without reporting; call close() to learn about failures

  // Flushes, closes and throws subdiv::Error for the first failure of any write.
  void close();
  // errno of the first failed write, 0 while every write succeeded.
  int error() const { return error_; }

protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* data, std::streamsize count) override;
  int sync() override;
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode which) override;
  pos_type seekpos(pos_type pos, std::ios_base::openmode which) override;

private:
  void flush_buffer();
  void put_bytes(const char* data, std::size_t count);

  static constexpr std::size_t kBufferSize = 1 << 20;
  int fd_ = -1;
  int error_ = 0;
  long long position_ = 0;  // file offset of the buffer's first byte
  long long end_ = 0;       // the largest offset written, for seeks relative to the end
  std::string shown_;
  std::unique_ptr<char[]> buffer_;
};

// std::ostream over a CheckedFileBuffer.
class CheckedFileStream : public std::ostream {
public:
  CheckedFileStream(const std::filesystem::path& file, const std::filesystem::path& shown);
  void close() { buffer_.close(); }
  int error() const { return buffer_.error(); }

private:
  CheckedFileBuffer buffer_;
};

}  // namespace subdiv
