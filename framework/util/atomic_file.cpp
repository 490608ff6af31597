#include "framework/util/atomic_file.h"

#include <atomic>
#include <random>
#include <system_error>

#include <fmt/format.h>

#include "framework/util/error.h"

namespace subdiv {
namespace fs = std::filesystem;

namespace {

// Unique per process and call, so concurrent writers of the same target do not collide;
// the leading dot keeps half-written files out of casual directory listings.
fs::path temporary_name(const fs::path& target) {
  static const unsigned long long salt = std::random_device{}();
  static std::atomic<unsigned long long> counter{0};
  return target.parent_path() /
         fmt::format(".{}.{:x}-{}.tmp", target.filename().string(), salt, counter++);
}

void require_directory(const fs::path& target) {
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw Error(fmt::format("cannot write '{}': directory '{}' does not exist; create it first",
                            target.string(), dir.string()));
}

void rename_into_place(const fs::path& tmp, const fs::path& target) {
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec)
    throw Error(fmt::format("cannot write '{}': renaming the finished temporary file failed ({})",
                            target.string(), ec.message()));
}

}  // namespace

void write_file_atomically(const fs::path& target,
                           const std::function<void(const fs::path& tmp)>& writer) {
  StagedFiles files;
  writer(files.stage(target));
  files.commit();
}

StagedFiles::~StagedFiles() { discard(); }

fs::path StagedFiles::stage(const fs::path& target) {
  require_directory(target);
  staged_.emplace_back(temporary_name(target), target);
  return staged_.back().first;
}

void StagedFiles::commit() {
  // Renaming cannot be undone for the files already moved, but the remaining temporaries
  // are still removed by discard(), so no stray half files stay behind.
  while (!staged_.empty()) {
    rename_into_place(staged_.front().first, staged_.front().second);
    staged_.erase(staged_.begin());
  }
}

void StagedFiles::discard() noexcept {
  for (const auto& [tmp, target] : staged_) {
    std::error_code ec;
    fs::remove(tmp, ec);
  }
  staged_.clear();
}

}  // namespace subdiv
