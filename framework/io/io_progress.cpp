#include "framework/io/io_progress.h"

#include <algorithm>
#include <mutex>

namespace subdiv::io_detail {
namespace {

// One read reports at a time per process (read_mesh installs the scope; nested reads, e.g.
// a sidecar file, report nothing of their own).
struct Reading {
  std::mutex mutex;
  std::atomic<const ProgressCallback*> report{nullptr};
  std::thread::id owner;
  std::size_t total = 0, step = 1;
  std::atomic<std::size_t> parsed{0}, next_tell{0};
};

Reading& reading() {
  static Reading r;
  return r;
}

void tell_if_due(Reading& r, std::size_t position) {
  if (position < r.next_tell.load(std::memory_order_relaxed) || std::this_thread::get_id() != r.owner) return;
  r.next_tell.store(position + r.step, std::memory_order_relaxed);
  (*r.report.load())(std::min(1.0, double(position) / double(r.total)));
}

}  // namespace

ReadProgressScope::ReadProgressScope(const ProgressCallback& report, std::size_t total_bytes) {
  Reading& r = reading();
  std::lock_guard lock(r.mutex);
  if (!report || r.report.load() || total_bytes == 0) return;
  r.owner = std::this_thread::get_id();
  r.total = total_bytes;
  r.step = std::max<std::size_t>(total_bytes / 256, 1 << 16);
  r.parsed = 0;
  r.next_tell = 0;
  r.report = &report;
  installed_ = true;
  report(0);
}

ReadProgressScope::~ReadProgressScope() {
  Reading& r = reading();
  std::lock_guard lock(r.mutex);
  if (!installed_) return;
  const ProgressCallback* report = r.report.exchange(nullptr);
  (*report)(1);
}

void read_position(std::size_t position) {
  Reading& r = reading();
  if (r.report) tell_if_due(r, position);
}

void read_advanced(std::size_t bytes) {
  Reading& r = reading();
  if (r.report) tell_if_due(r, r.parsed.fetch_add(bytes, std::memory_order_relaxed) + bytes);
}

WriteProgress::WriteProgress(const ProgressCallback& report, std::size_t total_elements)
    : report_(report), total_(std::max<std::size_t>(total_elements, 1)), next_(std::max<std::size_t>(total_ / 256, 1)) {
  if (report_) report_(0);
}

void WriteProgress::tell() {
  next_ = done_ + std::max<std::size_t>(total_ / 256, 1);
  if (report_) report_(std::min(1.0, double(done_) / double(total_)));
}

void WriteProgress::finish() {
  if (report_) report_(1);
}

}  // namespace subdiv::io_detail
