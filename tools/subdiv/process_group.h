#pragma once
// The processes that share a refinement in pieces: the ranks of mpirun when the tool was
// built with MPI (cmake/Pieces.cmake), else this process alone. Only the tool knows MPI;
// libsubdiv never does.
namespace subdiv::cli {

class ProcessGroup {
public:
  // Joins the group (MPI_Init on first use; MPI_Finalize when the program ends).
  static ProcessGroup& join();
  int rank() const { return rank_; }
  int size() const { return size_; }
  // True on every process when `ok` is true on every process; every process must call it.
  bool all(bool ok) const;
  // Waits for every process.
  void barrier() const;

private:
  ProcessGroup();
  int rank_ = 0, size_ = 1;
};

// "MPI" or "no MPI", for --help.
const char* process_group_kind();

}  // namespace subdiv::cli
