// Distributed rendering: `mpirun -np N safegi-render scene.json …` renders the
// image's tiles on N processes and writes it from rank 0, bit-identical to the
// single-process render (docs/cpu-renderer.md, "Distributed rendering"). Run
// without an MPI launcher (or built without MPI) the session is one process
// and render() is the plain render().
#pragma once

#include <exception>
#include <string>

#include "distributed/communicator.hpp"
#include "safegi/cpu_renderer/renderer.hpp"

namespace safegi::render {

class DistributedSession {
 public:
  DistributedSession(int& argc, char**& argv);

  int rank() const { return communicator_.rank(); }
  int ranks() const { return communicator_.size(); }
  // Rank 0 prints, shows the progress bar and writes the image.
  bool is_root() const { return rank() == 0; }
  // The ranks sharing this machine (its memory), and the worker threads a rank takes by default.
  int ranks_on_this_node() const { return communicator_.ranks_on_this_node(); }
  int default_threads() const;

  // Collective. First agrees that every rank's setup (scene, options)
  // succeeded; when one rank's failed, it throws on every rank (rank 0 has
  // printed the message, and report_error() adds nothing). Then this rank renders its
  // share, and rank 0 gathers the image and the statistics (rays, samples and
  // threads summed over ranks; seconds: rank 0's, until the image is whole).
  // The other ranks get an empty image.
  Image render(const Scene& scene, RenderOptions options, RenderStats* stats);

  // Collectives: the sum or the largest over ranks, on rank 0 (elsewhere: value).
  double sum_over_ranks(double value) { return communicator_.sum_to_first(value); }
  double max_over_ranks(double value) { return communicator_.max_to_first(value); }

  // What main() returns after catching `error`; prints it once for the job.
  // During setup it joins render()'s agreement, so that one error is printed
  // however many ranks fail, and no rank waits for a failed one. During the
  // render a rank cannot wait for the others: it prints the error with its
  // rank and ends the job. Afterwards (rank 0 writing the image) it prints
  // the error as a single process would. The status is kExitUsage for a
  // CommandLineError, else kExitInputError.
  int report_error(const std::exception& error);

 private:
  class Partition;
  enum class Phase { setup, rendering, reporting };

  void agree_setup(const std::string* error);
  void test_fault_point();
  Image gather_on_first(Image image);

  Communicator communicator_;
  Phase phase_ = Phase::setup;
  // Test-only (SAFEGI_RENDER_TEST_FAULT=setup|throw|kill:RANK): one rank fails
  // its setup, throws while rendering, or dies while rendering.
  std::string fault_kind_, fault_error_;
  int fault_rank_ = -1;
};

}  // namespace safegi::render
