#include "app/evaluators.h"

#include "app/validators.h"
#ifdef WALKERS_HAVE_MPI
#include "evolve/mpi_evaluator.h"
#endif

namespace walkers::app {
namespace {

// the MPI job's size, 1 outside one
int Ranks() {
#ifdef WALKERS_HAVE_MPI
  if (const mpi::Session* session = mpi::CurrentSession()) return session->size();
#endif
  return 1;
}

int Threads(const EvaluatorOptions& options) {
  if (Ranks() > 1) return options.threads > 0 ? options.threads : 1;
  return ThreadsOrAllCores(options.threads);
}

}  // namespace

void AddEvaluatorOptions(CLI::App* sub, EvaluatorOptions* options) {
  AddThreadsOption(sub, &options->threads);
  sub->add_option("--rank-timeout", options->rank_timeout_s,
                  "In an MPI job: seconds a rank may take for one evaluation before the job ends with an error")
      ->check(CLI::Range(1.0, 1e6))
      ->capture_default_str();
}

std::unique_ptr<Evaluator> MakeEvaluator(const EvaluatorOptions& options) {
#ifdef WALKERS_HAVE_MPI
  if (Ranks() > 1) return mpi::MakeMpiEvaluator(Threads(options), options.rank_timeout_s);
#endif
  return MakeThreadEvaluator(Threads(options));
}

std::string DescribeEvaluator(const EvaluatorOptions& options) {
  const int threads = Threads(options);
  const std::string on_threads = std::to_string(threads) + (threads == 1 ? " thread" : " threads");
  if (Ranks() > 1) return std::to_string(Ranks()) + " MPI ranks (" + on_threads + " on rank 0)";
  return on_threads;
}

}  // namespace walkers::app
