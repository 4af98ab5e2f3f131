// The communicator of a build without MPI: one process, rank 0 of 1, where
// every collective returns its own argument.
#include <cstdio>
#include <cstdlib>

#include "distributed/communicator.hpp"

namespace safegi::render {

Communicator::Communicator(int&, char**&) {
  if (started_by_mpi_launcher())
    std::fprintf(stderr,
                 "warning: this safegi-render was built without MPI (SAFEGI_WITH_MPI=OFF or MPI not found): "
                 "under mpirun every process renders the whole image by itself\n");
}
Communicator::~Communicator() = default;

void Communicator::wait_for_every_rank() {}
int Communicator::min_over_ranks(int value) { return value; }
int Communicator::sum_over_ranks(int value) { return value; }
void Communicator::broadcast(std::string&, int) {}
int Communicator::broadcast_from_first(int value) { return value; }
double Communicator::max_to_first(double value) { return value; }
double Communicator::sum_to_first(double value) { return value; }
void Communicator::sum_to_first(uint64_t*, int) {}
void Communicator::sum_to_first(double*, size_t) {}
void Communicator::send(const float*, size_t, int) {}
void Communicator::receive(float*, size_t, int) {}
void Communicator::abort(int exit_code) { std::exit(exit_code); }

}  // namespace safegi::render
