#include "framework/rules/stage_times.h"

#include <algorithm>
#include <ctime>

namespace subdiv {
namespace {

double now_ms(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

}  // namespace

void StageTimes::add(std::string_view name, double wall_ms, double cpu_ms) {
  std::lock_guard lock(mutex_);
  auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.name == name; });
  if (it == entries_.end()) it = entries_.insert(entries_.end(), Entry{std::string(name)});
  it->wall_ms += wall_ms, it->cpu_ms += cpu_ms, ++it->count;
}

std::vector<StageTimes::Entry> StageTimes::entries() const {
  std::lock_guard lock(mutex_);
  return entries_;
}

void StageTimes::clear() {
  std::lock_guard lock(mutex_);
  entries_.clear();
}

StageTimer::StageTimer(StageTimes* times, std::string name) : times_(times) {
  if (!times_) return;
  name_ = std::move(name);
  wall0_ = now_ms(CLOCK_MONOTONIC), cpu0_ = now_ms(CLOCK_PROCESS_CPUTIME_ID);
}

StageTimer::~StageTimer() {
  if (times_) times_->add(name_, now_ms(CLOCK_MONOTONIC) - wall0_, now_ms(CLOCK_PROCESS_CPUTIME_ID) - cpu0_);
}

}  // namespace subdiv
