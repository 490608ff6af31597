#include "framework/util/atomic_file.h"

#include <atomic>
#include <random>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <string_view>
#include <sys/file.h>
#include <system_error>
#include <unistd.h>

#include <fmt/format.h>

#include "framework/util/error.h"
#include "framework/util/input_file.h"
#include "framework/util/interrupt_cleanup.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace fs = std::filesystem;

namespace {

// Unique per process and call, so concurrent writers of the same target do not collide;
// the leading dot keeps half-written files out of casual directory listings. At most the
// first 100 bytes of the target's name go in, so that the temporary name stays within the
// file system's limit whenever the target's does.
std::string temporary_prefix(const fs::path& target) {
  return fmt::format(".{}.", target.filename().string().substr(0, 100));
}

fs::path temporary_name(const fs::path& target) {
  static const unsigned long long salt = std::random_device{}();
  static std::atomic<unsigned long long> counter{0};
  return target.parent_path() / fmt::format("{}{:x}-{}.tmp", temporary_prefix(target), salt, counter++);
}

// "<hex>-<decimal>", the part of a temporary's name temporary_name() makes after the prefix.
bool is_temporary_id(std::string_view id) {
  const size_t dash = id.find('-');
  if (dash == 0 || dash == std::string_view::npos || dash + 1 == id.size()) return false;
  for (size_t i = 0; i < id.size(); ++i) {
    const char c = id[i];
    const bool ok = i < dash ? (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') : i == dash || (c >= '0' && c <= '9');
    if (!ok) return false;
  }
  return true;
}

// Creates the temporary and takes its lock; the descriptor keeps the lock.
int create_locked(const fs::path& tmp, const fs::path& target) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0)
    throw Error(fmt::format("cannot write {}: cannot create a temporary file in its directory ({}); check the "
                            "directory's permissions and free space",
                            subdiv::quoted(target.string()), std::strerror(errno)));
  ::flock(fd, LOCK_EX | LOCK_NB);  // fresh file: nobody else can hold it
  return fd;
}

fs::path directory_of(const fs::path& target) {
  return target.parent_path().empty() ? fs::path(".") : target.parent_path();
}

void require_directory(const fs::path& target) {
  const fs::path dir = directory_of(target);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw Error(fmt::format("cannot write {}: directory {} does not exist; create it first",
                            subdiv::quoted(target.string()), subdiv::quoted(dir.string())));
}

// Checked before anything is written: a name the file system cannot hold would otherwise
// fail deep inside a writer (VTK's, with its own messages).
void require_name_fits(const fs::path& target) {
  const long limit = pathconf(directory_of(target).c_str(), _PC_NAME_MAX);
  const size_t length = target.filename().string().size();
  if (limit > 0 && length > size_t(limit))
    throw Error(fmt::format("cannot write {}: its file name is {} bytes long, more than the {} this file system "
                            "allows; choose a shorter name",
                            subdiv::quoted(target.string()), length, limit));
}

// Renaming the finished temporary would replace whatever the target is: as root, -o /dev/null
// or /dev/stdout (a link to a pipe) would turn the device or link into a plain file, and a
// FIFO a reader waits on would be swapped for a file it never sees. Only a regular file (or
// a link to one) is replaced; anything else is refused before a byte is written.
void require_regular_or_absent(const fs::path& target) {
  std::error_code ec;
  const fs::file_type type = fs::status(target, ec).type();  // follows links
  // Absent, regular, or not statable (the temporary's creation then says why).
  if (ec) return;
  if (type == fs::file_type::regular) {
    // Renaming the finished file onto it replaces it whatever its permissions (and root may
    // write anything): a file nobody may write is one its owner meant to keep.
    constexpr fs::perms writable = fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
    if ((fs::status(target, ec).permissions() & writable) == fs::perms::none && !ec)
      throw Error(fmt::format("cannot write {}: it is read-only (no write permission); make it writable (chmod u+w) "
                              "or name another output",
                              subdiv::quoted(target.string())));
    return;
  }
  if (type == fs::file_type::directory)
    throw Error(fmt::format("cannot write {}: it is a directory; name a file, in it or beside it",
                            subdiv::quoted(target.string())));
  throw Error(fmt::format("cannot write {}: it is {}, which writing would replace by a plain file; name a regular "
                          "file (SubdivKit writes files, not streams)",
                          subdiv::quoted(target.string()), file_type_name(type)));
}

void require_target(const fs::path& target) {
  require_directory(target);
  require_name_fits(target);
  require_regular_or_absent(target);
}

void rename_into_place(const fs::path& tmp, const fs::path& target) {
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec)
    throw Error(fmt::format("cannot write {}: renaming the finished temporary file failed ({})",
                            subdiv::quoted(target.string()), ec.message()));
}

}  // namespace

void write_file_atomically(const fs::path& target,
                           const std::function<void(const fs::path& tmp)>& writer) {
  StagedFiles files;
  writer(files.stage(target));
  files.commit();
}

int remove_stale_temporaries(const fs::path& target) {
  const std::string prefix = temporary_prefix(target);
  std::error_code ec;
  fs::directory_iterator it(directory_of(target), ec), end;
  int removed = 0;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + 4 || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - 4, 4, ".tmp") != 0 ||
        !is_temporary_id(std::string_view(name).substr(prefix.size(), name.size() - prefix.size() - 4)))
      continue;
    const int fd = ::open(it->path().c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0) continue;
    // A live writer holds the lock; the lock of a killed one went with its process.
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0 && ::unlink(it->path().c_str()) == 0) ++removed;
    ::close(fd);
  }
  return removed;
}

StagedFiles::~StagedFiles() { discard(); }

void check_writable(const fs::path& target) {
  require_target(target);
  // Permissions, a read-only file system, a full inode table: only creating a file tells
  // (access() says yes to root on a read-only folder). The probe is a temporary like
  // stage()'s, so one left by a kill is removed as theirs are.
  const fs::path probe = temporary_name(target);
  ::close(create_locked(probe, target));
  std::error_code ec;
  fs::remove(probe, ec);
}

fs::path StagedFiles::stage(const fs::path& target) {
  require_target(target);
  remove_stale_temporaries(target);
  const fs::path tmp = temporary_name(target);
  const int fd = create_locked(tmp, target);
  staged_.push_back({tmp, target, fd, track_temporary(tmp)});
  return tmp;
}

void StagedFiles::commit() {
  // Renaming cannot be undone for the files already moved, but the remaining temporaries
  // are still removed by discard(), so no stray half files stay behind.
  while (!staged_.empty()) {
    rename_into_place(staged_.front().tmp, staged_.front().target);
    untrack_temporary(staged_.front().signal_slot);
    ::close(staged_.front().lock_fd);
    staged_.erase(staged_.begin());
  }
}

void StagedFiles::discard() noexcept {
  for (const Staged& s : staged_) {
    std::error_code ec;
    fs::remove(s.tmp, ec);
    untrack_temporary(s.signal_slot);
    ::close(s.lock_fd);
  }
  staged_.clear();
}

}  // namespace subdiv
