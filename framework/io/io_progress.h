#pragma once
// Progress of reading and writing mesh files, for a front-end's bar (tools/subdiv/progress.h,
// Python's progress=): the share done, 0 to 1, told to a callback on the thread that started
// the read or write, a few hundred times at most however large the file.
//
// Readers report through the scope read_mesh opens (ReadProgressScope): the text readers'
// LineCursor as it passes bytes, the parallel OBJ path as its chunks finish (counted from any
// thread, told from the reading one). Writers count the elements they have written
// (WriteProgress). Internal to io/.
#include <atomic>
#include <cstddef>
#include <functional>
#include <thread>

namespace subdiv::io_detail {

using ProgressCallback = std::function<void(double done)>;

class ReadProgressScope {
public:
  // Reports reading `total_bytes` to `report` until the scope ends (nothing when it is empty).
  ReadProgressScope(const ProgressCallback& report, std::size_t total_bytes);
  ~ReadProgressScope();
  ReadProgressScope(const ReadProgressScope&) = delete;
  ReadProgressScope& operator=(const ReadProgressScope&) = delete;

private:
  bool installed_ = false;  // false for a read inside another (it reports nothing)
};

// The reader on this thread has passed `position` bytes of its file (sequential readers).
void read_position(std::size_t position);
// `bytes` more of the file are parsed, on any thread (the parallel OBJ path).
void read_advanced(std::size_t bytes);

// Counts a writer's elements (vertices, then faces) and tells `report` the share written
// every 1/256th of them.
class WriteProgress {
public:
  WriteProgress(const ProgressCallback& report, std::size_t total_elements);
  void step() {
    if (++done_ >= next_) tell();
  }
  void finish();

private:
  void tell();
  const ProgressCallback& report_;
  std::size_t total_, done_ = 0, next_;
};

}  // namespace subdiv::io_detail
