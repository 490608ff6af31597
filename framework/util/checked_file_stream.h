#pragma once
// An output stream for writers that cannot be trusted with a failing stream (VTK's XML
// writer crashes when its ofstream fails on a full disk: it reads back positions of a
// stream in a failed state). This stream never fails towards its user: the first write
// error is remembered, every later byte is dropped while positions still advance, and
// close() reports the error as subdiv::Error naming the target. Seeking is supported
// (VTK's appended mode goes back to fill in offsets): writes go to the file with pwrite at
// the stream's own position.
//
// Direct mode (FileWrite::Direct) writes the file in whole chunks with O_DIRECT, past the
// page cache, on a thread of its own (direct_chunk_writer.h); what goes back before the
// chunk being filled, and the last partial chunk, are written through the page cache at
// close(). The file's bytes are the same in both modes. Where O_DIRECT is refused (a file
// system without it, such as older tmpfs), it writes as in buffered mode.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <ostream>
#include <span>
#include <string>
#include <streambuf>
#include <utility>
#include <vector>

namespace subdiv {

class DirectChunkWriter;

// How CheckedFileBuffer writes: through the page cache, or in direct chunks (see above).
enum class FileWrite { Buffered, Direct };

// "cannot write '<shown>': ..." for the errno of a failed write; a full disk (or a file size
// limit) says so and how to go on.
std::string write_failure_text(const std::string& shown, int error);

class CheckedFileBuffer : public std::streambuf {
public:
  // Creates (or truncates) `file`; `shown` names it in messages (the target, not the
  // temporary). Throws subdiv::Error if the file cannot be created.
  CheckedFileBuffer(const std::filesystem::path& file, const std::filesystem::path& shown,
                    FileWrite mode = FileWrite::Buffered);
  CheckedFileBuffer(const CheckedFileBuffer&) = delete;
  CheckedFileBuffer& operator=(const CheckedFileBuffer&) = delete;
  ~CheckedFileBuffer() override;  // closes without reporting; call close() to learn about failures

  // Flushes, closes and throws subdiv::Error for the first failure of any write.
  void close();
  // errno of the first failed write, 0 while every write succeeded.
  int error() const { return error_; }

  // Room to write into in place, at the put position, for a writer that would otherwise make
  // its bytes in a buffer of its own and copy them in (the .vtp writer's base64 text, encoded
  // straight into direct mode's chunks); then commit() the bytes written there. At least one
  // byte unless the put position lies before the chunk being filled (after a seek back), where
  // it is empty and sputn is the way.
  std::span<char> room();
  // The first `count` bytes of room() written: the put position moves on past them.
  void commit(std::size_t count);

protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* data, std::streamsize count) override;
  int sync() override;
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode which) override;
  pos_type seekpos(pos_type pos, std::ios_base::openmode which) override;

private:
  void flush_buffer();
  void put_bytes(const char* data, std::size_t count);
  // Direct mode: the chunk's high-water mark from the put position; the next chunk when the
  // put area is full; the bytes at a position before the chunk, kept for close().
  void note_fill();
  void next_chunk();
  void start_patch(long long at);
  void seek_direct(long long to);
  void close_direct();

  static constexpr std::size_t kBufferSize = 1 << 20;
  int fd_ = -1;
  int error_ = 0;
  long long position_ = 0;  // file offset of the buffer's first byte
  long long end_ = 0;       // the largest offset written, for seeks relative to the end
  std::string shown_;
  std::unique_ptr<char[]> buffer_;
  // Direct mode: buffer_ is unused; the put area is the chunk at file offset position_,
  // written up to fill_ bytes. While patching_, writes land before position_ (a part already
  // submitted) and are kept in patches_ (offset, bytes) until close().
  std::unique_ptr<DirectChunkWriter> direct_;
  char* chunk_ = nullptr;
  std::size_t fill_ = 0;
  bool patching_ = false;
  std::vector<std::pair<long long, std::string>> patches_;
};

// std::ostream over a CheckedFileBuffer.
class CheckedFileStream : public std::ostream {
public:
  CheckedFileStream(const std::filesystem::path& file, const std::filesystem::path& shown,
                    FileWrite mode = FileWrite::Buffered);
  void close() { buffer_.close(); }
  int error() const { return buffer_.error(); }

private:
  CheckedFileBuffer buffer_;
};

}  // namespace subdiv
