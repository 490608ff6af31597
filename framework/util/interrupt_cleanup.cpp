#include "framework/util/interrupt_cleanup.h"

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace subdiv {
namespace {

// Fixed storage: a signal handler may neither allocate nor lock (only async-signal-safe
// calls: unlink, sigaction, raise).
constexpr int kSlots = 64;
constexpr size_t kPathBytes = 4096;

struct Slot {
  std::atomic<bool> used{false};  // owned by a tracker
  std::atomic<bool> armed{false}; // the path is complete: the handler may remove it
  char path[kPathBytes];
};

std::array<Slot, kSlots> slots;
constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (Slot& s : slots)
    if (s.armed.load(std::memory_order_acquire)) ::unlink(s.path);
  struct sigaction plain {};
  plain.sa_handler = SIG_DFL;
  sigemptyset(&plain.sa_mask);
  ::sigaction(signal_number, &plain, nullptr);
  ::raise(signal_number);  // ends the process as the signal would have (exit status 128 + n)
}

// Checked at every tracking, not once: a signal's disposition may be set back to the default
// later (a forked child, a host program restoring its own).
void install_where_default() {
  for (const int sig : kSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction handler {};
    handler.sa_handler = remove_temporaries_and_reraise;
    sigemptyset(&handler.sa_mask);
    ::sigaction(sig, &handler, nullptr);
  }
}

}  // namespace

int track_temporary(const std::filesystem::path& tmp) {
  const std::string& text = tmp.native();
  if (text.size() >= kPathBytes) return -1;
  install_where_default();
  for (int i = 0; i < kSlots; ++i) {
    bool expected = false;
    if (!slots[size_t(i)].used.compare_exchange_strong(expected, true)) continue;
    std::memcpy(slots[size_t(i)].path, text.c_str(), text.size() + 1);
    slots[size_t(i)].armed.store(true, std::memory_order_release);
    return i;
  }
  return -1;
}

void untrack_temporary(int slot) noexcept {
  if (slot < 0 || slot >= kSlots) return;
  slots[size_t(slot)].armed.store(false, std::memory_order_release);
  slots[size_t(slot)].used.store(false, std::memory_order_release);
}

}  // namespace subdiv
