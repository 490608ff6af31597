#include "framework/util/atomic_file.h"

#include <atomic>
#include <random>
#include <system_error>
#include <unistd.h>

#include <fmt/format.h>

#include "framework/util/error.h"

namespace subdiv {
namespace fs = std::filesystem;

namespace {

// Unique per process and call, so concurrent writers of the same target do not collide;
// the leading dot keeps half-written files out of casual directory listings. At most the
// first 100 bytes of the target's name go in, so that the temporary name stays within the
// file system's limit whenever the target's does.
fs::path temporary_name(const fs::path& target) {
  static const unsigned long long salt = std::random_device{}();
  static std::atomic<unsigned long long> counter{0};
  return target.parent_path() /
         fmt::format(".{}.{:x}-{}.tmp", target.filename().string().substr(0, 100), salt, counter++);
}

fs::path directory_of(const fs::path& target) {
  return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

void require_directory(const fs::path& target) {
  const fs::path dir = directory_of(target);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw Error(fmt::format("cannot write '{}': directory '{}' does not exist; create it first",
                            target.string(), dir.string()));
}

// Checked before anything is written: a name the file system cannot hold would otherwise
// fail deep inside a writer (VTK's, with its own messages).
void require_name_fits(const fs::path& target) {
  const long limit = pathconf(directory_of(target).c_str(), _PC_NAME_MAX);
  const size_t length = target.filename().string().size();
  if (limit > 0 && length > size_t(limit))
    throw Error(fmt::format("cannot write '{}': its file name is {} bytes long, more than the {} this file system "
                            "allows; choose a shorter name",
                            target.string(), length, limit));
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
  require_name_fits(target);
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
