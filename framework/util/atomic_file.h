#pragma once
// Writing files so that a reader never sees half of one: every file is written under a
// temporary name in its target directory and renamed into place only when complete.
// rename() within one directory is atomic on POSIX file systems, so a target is either
// the old file or the complete new one, never a mix. Each temporary is locked (flock) by
// its writer while it exists; writing a target again removes the unlocked temporaries of
// that target, which a killed run (kill -9, power loss) left behind; Ctrl-C, SIGTERM and
// SIGHUP remove them as they end the run (interrupt_cleanup.h).
#include <filesystem>
#include <functional>
#include <utility>
#include <vector>

namespace subdiv {

// Writes one file: `writer` fills the temporary path it is given; on success the temporary
// replaces `target`, on any exception it is removed and the exception propagates.
// Throws subdiv::Error if the target's directory does not exist or the rename fails.
void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& tmp)>& writer);

// Several files that must appear together (a .pvd and its level files). stage() hands
// out temporary paths; commit() renames them all into place in the order staged. If the
// object is destroyed without commit(), every temporary is removed.
class StagedFiles {
public:
  StagedFiles() = default;
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  ~StagedFiles();

  // A fresh temporary path next to `target`. Throws subdiv::Error if the directory of
  // `target` does not exist.
  std::filesystem::path stage(const std::filesystem::path& target);
  void commit();
  void discard() noexcept;

private:
  struct Staged {
    std::filesystem::path tmp, target;
    int lock_fd;  // holds the temporary's lock until it is renamed or removed
    int signal_slot;  // removal on an interrupt (interrupt_cleanup.h)
  };
  std::vector<Staged> staged_;
};

// Refuses, with the reason and the fix, a target that writing would fail on: its directory
// missing or not writable, a name too long, a directory or device in its place. Called for
// every output before a command does any work, so that a bad path does not cost the work.
void check_writable(const std::filesystem::path& target);

// Removes the temporaries of `target` (".<name>.<id>.tmp" beside it) that no live writer
// holds: leftovers of a killed run. Returns how many it removed. stage() calls it.
int remove_stale_temporaries(const std::filesystem::path& target);

}  // namespace subdiv
