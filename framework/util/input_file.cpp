#include "framework/util/input_file.h"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "framework/util/error.h"
#include "framework/util/byte_size_text.h"
#include "framework/util/memory_limit.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace fs = std::filesystem;

const char* file_type_name(fs::file_type type) {
  switch (type) {
    case fs::file_type::fifo: return "a FIFO (named pipe)";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::socket: return "a socket";
    case fs::file_type::directory: return "a directory";
    default: return "not a regular file";
  }
}

void check_input_file(const fs::path& file, std::string_view what) {
  std::error_code ec;
  // status() follows symlinks: a link to /dev/zero is judged by what it points to.
  const fs::file_status status = fs::status(file, ec);
  if (status.type() == fs::file_type::not_found)
    throw Error(fmt::format("cannot open {}: no such file", subdiv::quoted(file.string())));
  if (ec) throw Error(fmt::format("cannot open {}: {}", subdiv::quoted(file.string()), ec.message()));
  if (status.type() == fs::file_type::directory)
    throw Error(fmt::format("cannot open {}: it is a directory, not a {} file", subdiv::quoted(file.string()), what));
  if (status.type() != fs::file_type::regular)
    throw Error(fmt::format("cannot open {}: it is {}; give the path of a regular {} file", subdiv::quoted(file.string()),
                            file_type_name(status.type()), what));
  const auto size = fs::file_size(file, ec);
  if (ec) throw Error(fmt::format("cannot open {}: {}", subdiv::quoted(file.string()), ec.message()));
  // Readers hold at least the whole text; a file larger than the memory left cannot be read.
  const MemoryBudget budget = available_memory();
  if (double(size) > budget.bytes) {
    const auto [need_text, have_text] = byte_sizes_compared(double(size), budget.bytes);
    throw Error(fmt::format("cannot read {}: it is {}, more than the {} of memory this process may still use ({}); "
                            "split the {} file or raise the limit",
                            subdiv::quoted(file.string()), need_text, have_text, budget.source, what));
  }
  std::ifstream probe(file, std::ios::binary);
  if (!probe) throw Error(fmt::format("cannot open {}: {}", subdiv::quoted(file.string()), std::strerror(errno)));
}

std::string read_input_file(const fs::path& file, std::string_view what, std::uintmax_t max_bytes) {
  check_input_file(file, what);
  std::error_code ec;
  if (const auto size = fs::file_size(file, ec); !ec && size > max_bytes)
    throw Error(
        fmt::format("cannot read {}: it is {} bytes ({:.1f} MB), more than the {:.0f} MB a {} file may have; "
                    "is it the right file?",
                    subdiv::quoted(file.string()), size, double(size) / 1e6, double(max_bytes) / 1e6, what));
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw Error(fmt::format("cannot read {}: {}", subdiv::quoted(file.string()), std::strerror(errno)));
  return std::move(bytes).str();
}

std::string_view without_utf8_bom(std::string_view text) {
  return text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
}

}  // namespace subdiv
