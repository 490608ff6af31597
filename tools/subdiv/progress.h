#pragma once
// One-line progress on a terminal (stderr), silent when stderr is not a terminal.
#include <string>

namespace subdiv::cli {

class Progress {
public:
  Progress();
  ~Progress();
  void say(const std::string& message);  // replaces the current line
  void done();                            // ends the line

private:
  bool terminal_;
  bool open_ = false;
};

}  // namespace subdiv::cli
