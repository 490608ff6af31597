#include "framework/util/scratch_vector.h"

#include <cstdlib>
#include <cstring>
#include <string_view>

namespace subdiv {

bool& scratch_poison() {
  static bool poison = [] {
    const char* setting = std::getenv("SUBDIV_POISON_SCRATCH");
    return setting && std::string_view(setting) == "1";
  }();
  return poison;
}

void poison_bytes(void* data, std::size_t bytes) { std::memset(data, 0xA5, bytes); }

}  // namespace subdiv
