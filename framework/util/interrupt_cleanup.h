#pragma once
// Temporaries that an interrupt must not strand. A run stopped by Ctrl-C (SIGINT), SIGTERM or
// SIGHUP ends without unwinding, so StagedFiles' destructor never runs and its hidden
// temporary (".out.vtp.<id>.tmp") would stay beside the target until the next write of it.
// While a temporary is tracked, those signals remove it and then end the process as they
// would have. A signal whose handler is not the default one (Python's KeyboardInterrupt) is
// left alone: that handler decides, and unwinding cleans up.
#include <filesystem>

namespace subdiv {

// Starts removing `tmp` on the signals above; returns a slot for untrack_temporary, or -1
// when all slots are taken (the temporary is then removed by the next write of its target,
// as after kill -9).
int track_temporary(const std::filesystem::path& tmp);

// Stops tracking (the temporary was renamed into place or removed). Ignores -1.
void untrack_temporary(int slot) noexcept;

}  // namespace subdiv
