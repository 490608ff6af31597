#pragma once
// One exception type for every user-facing failure. The message names the file, the place
// and the fix; the command line prints it and exits non-zero.
#include <stdexcept>
#include <string>

namespace subdiv {

class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

}  // namespace subdiv
