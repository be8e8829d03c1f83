// One full 15 s evaluation of a genome: the unit of work of evolution.
#include <benchmark/benchmark.h>

#include "control/evaluation.h"

namespace walkers {
namespace {

void Evaluation(benchmark::State& st, const Preset& preset) {
  const Genome genome = DefaultGenome();
  EvaluationResult r;
  for (auto _ : st) {
    r = Evaluate(genome, preset);
    benchmark::DoNotOptimize(r);
  }
  st.SetItemsProcessed(st.iterations());
  st.counters["fitness"] = r.fitness;
  st.counters["cvode_steps"] = static_cast<double>(r.integrator_stats.steps);
  st.counters["rhs_evals"] = static_cast<double>(r.integrator_stats.rhs_evals);
}

BENCHMARK_CAPTURE(Evaluation, default_original, OriginalPreset())->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Evaluation, default_paper, PaperPreset())->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace walkers
