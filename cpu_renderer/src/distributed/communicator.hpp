// The few message-passing operations a distributed render needs, over
// MPI_COMM_WORLD (communicator_mpi.cpp) or, in a build without MPI, over the
// one process there is (communicator_single.cpp). distributed.cpp holds the
// logic; every MPI call is in communicator_mpi.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace safegi::render {

// mpirun (Open MPI), the PMIx and PMI launchers (MPICH's hydra, Slurm) set these.
inline bool started_by_mpi_launcher() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(variable)) return true;
  return false;
}

class Communicator {
 public:
  // Joins the MPI job when the program was started by an MPI launcher
  // (mpirun sets OMPI_COMM_WORLD_SIZE, PMIX_RANK or PMI_SIZE); otherwise, or
  // without MPI, this process is rank 0 of 1 and MPI is never initialised, so
  // a plain run neither pays for MPI nor depends on its runtime.
  Communicator(int& argc, char**& argv);
  ~Communicator();  // MPI_Finalize when MPI was initialised
  Communicator(const Communicator&) = delete;
  Communicator& operator=(const Communicator&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  int ranks_on_this_node() const { return local_size_; }

  // Collectives: every rank calls them in the same order.
  // Returns once every rank has called it. A rank that arrives early sleeps
  // (1 ms at a time) instead of spinning in MPI's progress loop, as blocking
  // MPI calls do: on a node with more ranks than cores, spinning would take
  // the CPU from the ranks still rendering.
  void wait_for_every_rank();
  int min_over_ranks(int value);                  // on every rank
  int sum_over_ranks(int value);                  // on every rank
  void broadcast(std::string& text, int root);    // root's text on every rank
  int broadcast_from_first(int value);            // rank 0's value on every rank
  double max_to_first(double value);              // on rank 0 (elsewhere: value)
  double sum_to_first(double value);              // on rank 0 (elsewhere: value)
  void sum_to_first(uint64_t* values, int count);  // in place, on rank 0
  void sum_to_first(double* values, size_t count);  // in place, on rank 0 (any size: in pieces)

  // Point to point (any size: sent in pieces below MPI's int counts).
  void send(const float* values, size_t count, int to);
  void receive(float* values, size_t count, int from);

  // Ends every rank of the job (MPI_Abort); the launcher reports it.
  [[noreturn]] void abort(int exit_code);

 private:
  bool initialised_ = false;
  int rank_ = 0, size_ = 1, local_size_ = 1;
};

}  // namespace safegi::render
