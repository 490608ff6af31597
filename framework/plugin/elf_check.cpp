#include "framework/plugin/elf_check.h"

#include <cerrno>
#include <cstring>
#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

namespace subdiv {

namespace {

// The ELF types of this build (<link.h>'s ElfW): a plugin must match the process.
using Header = ElfW(Ehdr);
using ProgramHeader = ElfW(Phdr);
using SectionHeader = ElfW(Shdr);

constexpr unsigned char kClass = sizeof(void*) == 8 ? ELFCLASS64 : ELFCLASS32;
constexpr unsigned char kData = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? ELFDATA2LSB : ELFDATA2MSB;
// A library larger than this is not a plugin worth reading whole to check.
constexpr std::size_t kMaxPluginBytes = std::size_t(1) << 30;

bool fits(std::uint64_t offset, std::uint64_t size, std::size_t total) {
  return offset <= total && size <= total - offset;
}

template <typename T>
T read_at(std::string_view bytes, std::uint64_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

std::string cut_off(const char* what, std::uint64_t end, std::size_t size) {
  return fmt::format("the file is cut off or damaged: its {} end at byte {}, but the file has {} bytes (a copy "
                     "that did not finish?)",
                     what, end, size);
}

}  // namespace

std::optional<std::string> elf_problem(std::string_view bytes) {
  if (bytes.size() < sizeof(Header) || std::memcmp(bytes.data(), ELFMAG, SELFMAG) != 0)
    return bytes.size() >= SELFMAG && std::memcmp(bytes.data(), ELFMAG, SELFMAG) == 0
               ? cut_off("ELF header would", sizeof(Header), bytes.size())
               : std::string("not a shared library (no ELF header)");
  const auto h = read_at<Header>(bytes, 0);
  if (h.e_ident[EI_CLASS] != kClass || h.e_ident[EI_DATA] != kData)
    return fmt::format("built for another machine ({}-bit {}), this SubdivKit is {}-bit {}",
                       h.e_ident[EI_CLASS] == ELFCLASS64 ? 64 : 32,
                       h.e_ident[EI_DATA] == ELFDATA2MSB ? "big-endian" : "little-endian", sizeof(void*) * 8,
                       kData == ELFDATA2MSB ? "big-endian" : "little-endian");
  if (h.e_type != ET_DYN) return std::string("not a shared library (an ELF file of another type)");
  if (h.e_phentsize != sizeof(ProgramHeader) || h.e_phnum == 0)
    return std::string("the ELF program header table is missing or damaged");
  if (!fits(h.e_phoff, std::uint64_t(h.e_phnum) * sizeof(ProgramHeader), bytes.size()))
    return cut_off("program headers", h.e_phoff + std::uint64_t(h.e_phnum) * sizeof(ProgramHeader), bytes.size());
  for (unsigned i = 0; i < h.e_phnum; ++i) {
    const auto p = read_at<ProgramHeader>(bytes, h.e_phoff + std::uint64_t(i) * sizeof(ProgramHeader));
    if (p.p_type == PT_LOAD && !fits(p.p_offset, p.p_filesz, bytes.size()))
      return cut_off("loadable segments", p.p_offset + p.p_filesz, bytes.size());
  }
  if (h.e_shnum == 0) return std::string("the ELF section header table is missing (a stripped or damaged file)");
  if (h.e_shentsize != sizeof(SectionHeader)) return std::string("the ELF section header table is damaged");
  if (!fits(h.e_shoff, std::uint64_t(h.e_shnum) * sizeof(SectionHeader), bytes.size()))
    return cut_off("section headers", h.e_shoff + std::uint64_t(h.e_shnum) * sizeof(SectionHeader), bytes.size());
  for (unsigned i = 0; i < h.e_shnum; ++i) {
    const auto s = read_at<SectionHeader>(bytes, h.e_shoff + std::uint64_t(i) * sizeof(SectionHeader));
    if (s.sh_type != SHT_NOBITS && s.sh_type != SHT_NULL && !fits(s.sh_offset, s.sh_size, bytes.size()))
      return cut_off("sections", s.sh_offset + s.sh_size, bytes.size());
  }
  return std::nullopt;
}

std::optional<std::string> plugin_file_problem(const std::filesystem::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return fmt::format("cannot read it ({})", std::strerror(errno));
  if (S_ISDIR(st.st_mode)) return std::string("is a folder, not a library");
  if (!S_ISREG(st.st_mode))
    return std::string("not a regular file (a FIFO, socket or device); a plugin is a shared library file");
  if (std::size_t(st.st_size) > kMaxPluginBytes)
    return fmt::format("{} bytes, too large for a plugin (at most {})", st.st_size, kMaxPluginBytes);
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return fmt::format("cannot read it ({})", std::strerror(errno));
  std::string bytes(std::size_t(st.st_size), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += std::size_t(n);
  }
  ::close(fd);
  bytes.resize(got);
  return elf_problem(bytes);
}

}  // namespace subdiv
