// Evaluations shared over the ranks of an MPI job (Open MPI's mpirun, or
// Slurm's srun): rank 0 runs the program as one process would, owning the
// folders, the files and the progress; every other rank only evaluates the
// children rank 0 sends it. A result depends only on its task, so the files
// are the same for any number of ranks.
//
// Built with WALKERS_MPI (CMakeLists.txt); without it, no MPI.
#pragma once

#include <memory>

#include "evolve/evaluator.h"

namespace walkers::mpi {

// Whether an MPI launcher (mpirun, srun) started this process: its
// environment says so. A program started otherwise never initialises MPI.
bool LaunchedByLauncher();

// MPI from MPI_Init_thread to MPI_Finalize, for main. Rank 0 calls
// Finish(status) when its command is done: the other ranks are told to stop
// and each answers before MPI_Finalize (which waits for every rank). After a
// rank failed (RankFailed), or if one does not answer the stop within
// --rank-timeout, the job is aborted so that no rank is left waiting.
class Session {
 public:
  Session(int* argc, char*** argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // Rank 0: the other ranks stop (or the job is aborted with `status`, 1 if
  // it is 0, if a rank failed or does not answer). Returns `status`.
  int Finish(int status);

 private:
  int rank_ = 0;
  int size_ = 1;
  bool finished_ = false;
};

// The session of this process, or null outside an MPI job.
Session* CurrentSession();

// Ranks other than 0: evaluates what rank 0 sends until it says stop.
void ServeEvaluations();

// Rank 0: an evaluator of `threads` threads of this process and of every
// other rank, one evaluation at a time each (run one rank per core). A rank
// that gives no answer within `rank_timeout_s` of being sent a child makes
// EvaluateAll throw an error naming it; the job must then end (Session::Finish).
std::unique_ptr<Evaluator> MakeMpiEvaluator(int threads, double rank_timeout_s);

// Whether a rank failed (its answer did not come in time).
bool RankFailed();

}  // namespace walkers::mpi
