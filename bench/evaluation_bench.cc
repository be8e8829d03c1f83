// One 15 s evaluation per genome of the benchmark set, the whole set under
// each numerical variant, and one generation of 16 on 2 threads.
//
//   evaluation_bench --benchmark_filter=Genome/bench     per genome of the benchmark set, production settings
//   evaluation_bench --benchmark_filter=Genome/authors   per genome of the authors' final archives
//   evaluation_bench --benchmark_filter=Integrator   the benchmark set under CVODE and RK-Merson, genome by
//                                                    genome (add --benchmark_enable_random_interleaving=true
//                                                    to alternate their repetitions)
//   evaluation_bench --benchmark_filter=Variant      the choices of docs/performance.md
//   evaluation_bench --benchmark_filter=ByGenome/NAME/   one variant genome by genome, with its restarts
//                                                    and located switches
//   evaluation_bench --benchmark_filter=Generation   16 children on 2 threads
//   evaluation_bench --benchmark_filter=Batch        bench/walkers_module_bench.py's 16 genomes on 2 threads
#include <memory>

#include <benchmark/benchmark.h>

#include "bench/genome_set.h"
#include "bench/variants.h"
#include "control/evaluation.h"
#include "evolve/evaluator.h"
#include "evolve/genetic_algorithm.h"

namespace walkers::bench {
namespace {

void EvaluateGenome(benchmark::State& st, const Genome& genome, const EvaluationSettings& settings) {
  EvaluationResult r;
  for (auto _ : st) {
    r = Evaluate(genome, OriginalPreset(), settings);
    benchmark::DoNotOptimize(r);
  }
  st.SetItemsProcessed(st.iterations());
  st.counters["fitness"] = r.fitness;
  st.counters["steps"] = static_cast<double>(r.integrator_stats.steps);
  st.counters["rhs_evals"] = static_cast<double>(r.integrator_stats.rhs_evals);
  st.counters["restarts"] = static_cast<double>(r.integrator_stats.restarts);
  st.counters["switches_located"] = static_cast<double>(r.integrator_stats.switches_located);
}

// the whole set under one variant: items are evaluations
void EvaluateSet(benchmark::State& st, const EvaluationSettings& settings) {
  const auto genomes = BenchmarkGenomes();
  long steps = 0;
  for (auto _ : st) {
    steps = 0;
    for (const auto& [name, genome] : genomes) {
      const EvaluationResult r = Evaluate(genome, OriginalPreset(), settings);
      steps += r.integrator_stats.steps;
      benchmark::DoNotOptimize(r);
    }
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long>(genomes.size()));
  st.counters["cvode_steps_per_eval"] = static_cast<double>(steps) / genomes.size();
}

// generation 0 of a run: the default genome and 15 mutants, on 2 threads
void Generation(benchmark::State& st) {
  GeneticAlgorithmConfig config;
  Archive archive(config.archive_size);
  std::set<GenomeKey> seen;
  const std::vector<Individual> children = Breed(config, {1, 0, kBodyCeiling, MutationRules{}}, archive, &seen);
  const std::unique_ptr<Evaluator> evaluator = MakeThreadEvaluator(2);  // its threads started once
  const Preset preset = OriginalPreset();
  const EvaluationSettings settings;
  for (auto _ : st) {
    std::vector<Individual> batch = children;
    EvaluateIndividuals(*evaluator, &batch, preset, settings);
    benchmark::DoNotOptimize(batch);
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long>(children.size()));
}

// The 16 genomes bench/walkers_module_bench.py evaluates from Python (the
// benchmark set and the first 7 of the authors'), in its order, on 2 threads:
// what evaluate_batch(rows, threads=2) does, without Python.
void Batch(benchmark::State& st) {
  std::vector<Genome> genomes;
  for (const auto& [name, genome] : GenomeSet("bench")) genomes.push_back(genome);
  const auto authors = GenomeSet("authors");
  for (std::size_t i = 0; i < 7 && i < authors.size(); ++i) genomes.push_back(authors[i].second);
  const std::unique_ptr<Evaluator> evaluator = MakeThreadEvaluator(2);  // its threads started once
  const Preset preset = OriginalPreset();
  const EvaluationSettings settings;
  std::vector<EvaluationResult> results(genomes.size());
  std::vector<EvaluationTask> tasks;
  for (std::size_t i = 0; i < genomes.size(); ++i) tasks.push_back({&genomes[i], &preset, &settings, &results[i]});
  for (auto _ : st) {
    evaluator->EvaluateAll(tasks);
    benchmark::DoNotOptimize(results);
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long>(genomes.size()));
}

const bool kRegistered = [] {
  for (const char* set : {"bench", "authors"}) {
    for (const auto& [name, genome] : GenomeSet(set)) {
      benchmark::RegisterBenchmark(("Genome/" + std::string(set) + "/" + name).c_str(), EvaluateGenome, genome,
                                   EvaluationSettings{})
          ->Unit(benchmark::kMillisecond);
    }
  }
  // the authors' integrator beside CVODE, without the cut-off: every walk to its end
  for (const auto& [name, genome] : GenomeSet("bench")) {
    for (const char* method : {"cvode", "rk-merson"}) {
      benchmark::RegisterBenchmark(("Integrator/" + name + "/" + method).c_str(), EvaluateGenome, genome,
                                   SettingsOfIntegrator(method, std::nullopt, 0))
          ->Unit(benchmark::kMillisecond);
    }
  }
  // each variant on each genome of the benchmark set: its steps, restarts and located switches
  for (const Variant& v : Variants()) {
    for (const auto& [name, genome] : GenomeSet("bench")) {
      benchmark::RegisterBenchmark(("ByGenome/" + v.name + "/" + name).c_str(), EvaluateGenome, genome,
                                   v.settings)
          ->Unit(benchmark::kMillisecond);
    }
  }
  for (const Variant& v : Variants()) {
    // slow variants take seconds per set: a fixed small number of iterations
    benchmark::RegisterBenchmark(("Variant/" + v.name).c_str(), EvaluateSet, v.settings)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
  benchmark::RegisterBenchmark("Batch/16_genomes_2_threads", Batch)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(1);
  benchmark::RegisterBenchmark("Generation/16_children_2_threads", Generation)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  return true;
}();

}  // namespace
}  // namespace walkers::bench
