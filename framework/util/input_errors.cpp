#include "framework/util/input_errors.h"

#include <fmt/format.h>
#include <stdexcept>

#include "framework/util/memory_limit.h"
#include "framework/util/short_text.h"
#include "framework/util/quoted_text.h"

namespace subdiv {

std::string unexpected_read_failure(const std::string& file, const std::exception& e) {
  // The exception's kind says more than its text: length_error and out_of_range come from
  // sizes or offsets in the file that cannot be right.
  const char* kind = dynamic_cast<const std::length_error*>(&e)   ? "a size in it is impossible"
                     : dynamic_cast<const std::out_of_range*>(&e) ? "an index or offset in it is out of range"
                                                                  : "the reader failed";
  return fmt::format("cannot read {}: {} ({}); the file is damaged or not in the format its extension says",
                     subdiv::quoted(file), kind, shortened(e.what()));
}

std::string read_out_of_memory(const std::string& file) {
  return fmt::format("cannot read {}: {}", subdiv::quoted(file), out_of_memory_message("reading it", "give a smaller file"));
}

}  // namespace subdiv
