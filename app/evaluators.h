// What evolve and reproduce evaluate on: threads of this process, or, under
// mpirun or srun, those and the job's other ranks (evolve/mpi_evaluator.h).
#pragma once

#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "evolve/evaluator.h"

namespace walkers::app {

struct EvaluatorOptions {
  int threads = 0;                // 0: every core (in an MPI job: 1, a rank per core)
  double rank_timeout_s = 300.0;  // in an MPI job: how long a rank may take for one evaluation
};

// --threads and --rank-timeout
void AddEvaluatorOptions(CLI::App* sub, EvaluatorOptions* options);

std::unique_ptr<Evaluator> MakeEvaluator(const EvaluatorOptions& options);

// "2 threads", "3 MPI ranks (1 thread on rank 0)": for the progress lines
std::string DescribeEvaluator(const EvaluatorOptions& options);

}  // namespace walkers::app
