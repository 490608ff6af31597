#include "process_group.h"

#include <cstdlib>

#ifdef SUBDIV_HAVE_MPI
#include <mpi.h>
#endif

namespace subdiv::cli {

#ifdef SUBDIV_HAVE_MPI
namespace {

void finalize_at_exit() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

}  // namespace

ProcessGroup::ProcessGroup() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    MPI_Init(nullptr, nullptr);
    std::atexit(finalize_at_exit);
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

bool ProcessGroup::all(bool ok) const {
  int mine = ok ? 1 : 0, every = 0;
  MPI_Allreduce(&mine, &every, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return every == 1;
}

void ProcessGroup::barrier() const { MPI_Barrier(MPI_COMM_WORLD); }

const char* process_group_kind() { return "MPI"; }
#else
ProcessGroup::ProcessGroup() = default;
bool ProcessGroup::all(bool ok) const { return ok; }
void ProcessGroup::barrier() const {}
const char* process_group_kind() { return "no MPI"; }
#endif

ProcessGroup& ProcessGroup::join() {
  static ProcessGroup group;
  return group;
}

}  // namespace subdiv::cli
