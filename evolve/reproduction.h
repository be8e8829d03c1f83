// A reproduction of the paper's results: the three scaffolds, each with
// several replicate runs, then their statistics and the data of the figures.
//
// DIR/<case>-<replicate>/   one evolution run each (evolve/run.h)
// DIR/summary.json          statistics beside the paper's values (evolve/analysis.h)
// DIR/summary.md            the same as tables a person reads
// DIR/walks.json            the best biped's and best tripod's walks (control/walk_record.h)
// DIR/gallery.json          every run's final best and, if that is a biped, its
//                           best tripod, standing, to scale
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "control/evaluation.h"
#include "control/preset.h"
#include "evolve/analysis.h"
#include "evolve/genetic_algorithm.h"
#include "evolve/run.h"

namespace walkers {

struct ReproductionConfig {
  Preset preset = OriginalPreset();
  int generations = 4000;
  int replicates = 3;
  std::uint64_t seed = 1;  // replicate r of every case runs with seed + r - 1
  GeneticAlgorithmConfig ga;
  EvaluationSettings evaluation;

  void Validate() const;
};

struct PlannedRun {
  ScaffoldCase scaffold_case;
  int replicate;
  std::string name;  // "<case>-<replicate>"
  RunConfig config;
};

std::vector<PlannedRun> PlanRuns(const ReproductionConfig& config);

// Called before each run starts (with how many generations it has done) and
// after each of its generations.
struct ReproductionObserver {
  std::function<void(const PlannedRun&, int completed_generations)> on_run_start;
  std::function<void(const PlannedRun&, const GenerationSummary&)> on_generation;
};

// Runs (or resumes) every run, then writes the summary and figure data.
// Without `resume` a directory that holds any of the runs is refused.
ReproductionSummary Reproduce(const ReproductionConfig& config, const std::string& dir, bool resume, int threads,
                              const ReproductionObserver& observer = {});

// Only the analysis: reads the finished runs in DIR and writes summary.json,
// summary.md, walks.json and gallery.json.
ReproductionSummary WriteReproductionResults(const ReproductionConfig& config, const std::string& dir);

}  // namespace walkers
