// The communicator over MPI_COMM_WORLD (the C API of MPI 3; Debian's Open MPI).
// Without these, <mpi.h> in C++ pulls in the removed C++ bindings, whose
// library the C target does not link.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <thread>

#include "distributed/communicator.hpp"

namespace safegi::render {

namespace {

// MPI counts are ints: large buffers travel in pieces of at most this many floats.
constexpr size_t kPieceFloats = size_t{1} << 28;

}  // namespace

Communicator::Communicator(int& argc, char**& argv) {
  if (!started_by_mpi_launcher()) return;
  // Only the main thread calls MPI; the render threads never do.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &local_size_);
  MPI_Comm_free(&node);
}

Communicator::~Communicator() {
  if (initialised_) MPI_Finalize();
}

void Communicator::wait_for_every_rank() {
  if (!initialised_) return;
  MPI_Request barrier;
  MPI_Ibarrier(MPI_COMM_WORLD, &barrier);
  for (int done = 0;;) {
    MPI_Test(&barrier, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

int Communicator::min_over_ranks(int value) {
  int result = value;
  if (initialised_) MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return result;
}

int Communicator::sum_over_ranks(int value) {
  int result = value;
  if (initialised_) MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  return result;
}

void Communicator::broadcast(std::string& text, int root) {
  if (!initialised_) return;
  constexpr size_t kLongest = 1 << 20;  // error messages; a longer one is cut
  if (rank_ == root && text.size() > kLongest) text.resize(kLongest);
  int length = static_cast<int>(text.size());
  MPI_Bcast(&length, 1, MPI_INT, root, MPI_COMM_WORLD);
  text.resize(length);
  MPI_Bcast(text.data(), length, MPI_CHAR, root, MPI_COMM_WORLD);
}

int Communicator::broadcast_from_first(int value) {
  if (initialised_) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

double Communicator::max_to_first(double value) {
  double result = value;
  if (initialised_) MPI_Reduce(&value, &result, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
  return rank_ == 0 ? result : value;
}

double Communicator::sum_to_first(double value) {
  double result = value;
  if (initialised_) MPI_Reduce(&value, &result, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  return rank_ == 0 ? result : value;
}

void Communicator::sum_to_first(uint64_t* values, int count) {
  if (!initialised_) return;
  MPI_Reduce(rank_ == 0 ? MPI_IN_PLACE : values, values, count, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
}

void Communicator::sum_to_first(double* values, size_t count) {
  if (!initialised_) return;
  for (size_t done = 0; done < count; done += kPieceFloats)
    MPI_Reduce(rank_ == 0 ? MPI_IN_PLACE : values + done, values + done,
               static_cast<int>(std::min(kPieceFloats, count - done)), MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
}

void Communicator::send(const float* values, size_t count, int to) {
  for (size_t done = 0; done < count; done += kPieceFloats)
    MPI_Send(values + done, static_cast<int>(std::min(kPieceFloats, count - done)), MPI_FLOAT, to, 0, MPI_COMM_WORLD);
}

void Communicator::receive(float* values, size_t count, int from) {
  for (size_t done = 0; done < count; done += kPieceFloats)
    MPI_Recv(values + done, static_cast<int>(std::min(kPieceFloats, count - done)), MPI_FLOAT, from, 0, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
}

void Communicator::abort(int exit_code) {
  if (initialised_) MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::exit(exit_code);
}

}  // namespace safegi::render
