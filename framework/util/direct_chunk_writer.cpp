#include "framework/util/direct_chunk_writer.h"

#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <new>
#include <unistd.h>

namespace subdiv {

void DirectChunkWriter::Free::operator()(char* p) const { std::free(p); }

DirectChunkWriter::DirectChunkWriter(int fd, std::size_t chunk_size, std::size_t chunks)
    : fd_(fd), chunk_size_(chunk_size) {
  for (std::size_t i = 0; i < chunks; ++i) {
    auto* chunk = static_cast<char*>(std::aligned_alloc(kAlignment, chunk_size));
    if (!chunk) throw std::bad_alloc();
    memory_.emplace_back(chunk);
    free_.push_back(chunk);
  }
}

DirectChunkWriter::~DirectChunkWriter() { finish(); }

char* DirectChunkWriter::acquire() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return !free_.empty(); });
  char* chunk = free_.front();
  free_.pop_front();
  return chunk;
}

void DirectChunkWriter::submit(char* chunk, long long offset) {
  {
    std::lock_guard lock(mutex_);
    queue_.emplace_back(chunk, offset);
    if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
  }
  changed_.notify_all();
}

int DirectChunkWriter::finish() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
  return error_;
}

void DirectChunkWriter::run() {
  for (;;) {
    std::pair<char*, long long> job;
    bool failed;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return !queue_.empty() || stop_; });
      if (queue_.empty()) return;
      job = queue_.front();
      queue_.pop_front();
      failed = error_ != 0;
    }
    const int error = failed ? 0 : write_chunk(job.first, job.second);
    {
      std::lock_guard lock(mutex_);
      if (error != 0 && error_ == 0) error_ = error;
      free_.push_back(job.first);
    }
    changed_.notify_all();
  }
}

int DirectChunkWriter::write_chunk(const char* chunk, long long offset) {
  std::size_t done = 0;
  while (done < chunk_size_) {
    const ssize_t written = ::pwrite(fd_, chunk + done, chunk_size_ - done, off_t(offset + (long long)done));
    if (written < 0 && errno == EINTR) continue;
    if (written < 0 && errno == EINVAL) {
      // Direct I/O refused here (an alignment this file system or disk does not take, or the
      // rest of a write cut short by a file size limit): the rest through the page cache.
      const int flags = ::fcntl(fd_, F_GETFL);
      if (flags >= 0 && (flags & O_DIRECT) && ::fcntl(fd_, F_SETFL, flags & ~O_DIRECT) == 0) continue;
      return EINVAL;
    }
    if (written < 0) return errno;
    if (written == 0) return ENOSPC;
    done += std::size_t(written);
  }
  return 0;
}

}  // namespace subdiv
