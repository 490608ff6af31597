#pragma once
// Whole chunks of a file written with direct I/O (O_DIRECT: from this memory to the disk,
// past the page cache) on a thread of its own, so that the thread filling the next chunk
// keeps working while the disk takes the last one. Used by CheckedFileBuffer's direct mode.
//
// Why: a buffered write() copies every byte into new page-cache pages, and on a virtual
// machine that returns freed memory to its host each new page is first touched at a high
// price; writing 800 MB cost 0.65-2 s of system time that way, and a buffered write
// right after another ran at 0.2 GB/s, against 1.6-1.8 GB/s and 0.1 s with O_DIRECT
// (docs/benchmarks.md, "Writing and reading").
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace subdiv {

class DirectChunkWriter {
public:
  // Address, offset and length alignment of every direct write: a multiple of the 512-byte
  // and 4096-byte logical blocks of disks. A file system or device that wants another makes
  // the write fail with EINVAL, and the writer goes on through the page cache.
  static constexpr std::size_t kAlignment = 4096;

  // `fd` is open for writing, with O_DIRECT (or without: then the chunks go through the page
  // cache, written as they are); `chunk_size` a multiple of kAlignment; `chunks` the chunks in
  // flight or waiting at most, and so the memory it holds.
  DirectChunkWriter(int fd, std::size_t chunk_size, std::size_t chunks);
  DirectChunkWriter(const DirectChunkWriter&) = delete;
  DirectChunkWriter& operator=(const DirectChunkWriter&) = delete;
  ~DirectChunkWriter();  // waits for the chunks submitted

  std::size_t chunk_size() const { return chunk_size_; }
  // A chunk to fill (aligned), waiting while every chunk is submitted and not yet written.
  char* acquire();
  // Writes the whole of `chunk` (from acquire) at `offset` (a multiple of kAlignment), in
  // the order submitted; after a failure later chunks are dropped.
  void submit(char* chunk, long long offset);
  // Waits until every submitted chunk is written; the errno of the first failed write, 0 if
  // none failed.
  int finish();

private:
  struct Free {
    void operator()(char* p) const;
  };
  void run();
  int write_chunk(const char* chunk, long long offset);

  int fd_;
  std::size_t chunk_size_;
  std::vector<std::unique_ptr<char, Free>> memory_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<char*> free_;
  std::deque<std::pair<char*, long long>> queue_;
  std::size_t writing_ = 0;  // taken from the queue, not yet written
  bool stop_ = false;
  int error_ = 0;
  std::thread thread_;  // started with the first chunk submitted
};

}  // namespace subdiv
