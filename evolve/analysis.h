// The statistics of a reproduction (paper §3): per case, the best fitness
// over replicates at given generations; case 3 against case 1 and case 2
// against case 1; tripods among the final bests; the best biped against the
// best tripod; falls; time. Computed from what the runs wrote.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "control/genome.h"
#include "evolve/scaffold.h"

namespace walkers {

// One evaluated individual, as evaluations.csv holds it.
struct EvaluatedSummary {
  std::string run;  // "performance-2"
  std::string id;   // "3120/4"
  double fitness = 0;
  bool fell = false;
  bool tripod = false;
  Genome genome;    // read only for the bests kept
};

// What the analysis needs of one run.
struct RunData {
  std::string learner;  // its name in Learners()
  ScaffoldCase scaffold_case = ScaffoldCase::kFree;
  int replicate = 1;
  std::string name;                   // "free-1"
  std::vector<double> best_fitness;   // per generation (generations.csv)
  std::vector<bool> best_is_tripod;   // per generation
  double evaluation_seconds = 0;      // sum over generations of evaluations / evals_per_s
  long evaluations = 0;
  long falls = 0;
  std::optional<EvaluatedSummary> best_biped, best_tripod;  // over all its evaluations
};

// Reads DIR/generations.csv and DIR/evaluations.csv. Throws naming the file on bad data.
RunData LoadRunData(const std::string& dir, ScaffoldCase scaffold_case, int replicate, const std::string& name);

struct MeanSd {
  double mean = 0, sd = 0;  // sd: sample standard deviation (0 for one replicate)
  int n = 0;
};
MeanSd MeanAndSd(const std::vector<double>& values);

struct CaseSummary {
  ScaffoldCase scaffold_case = ScaffoldCase::kFree;
  int runs = 0;
  std::vector<std::pair<int, MeanSd>> best_after;  // (generations completed, best fitness over replicates)
  std::vector<double> mean_best;                   // per generation, over replicates
  std::vector<double> sd_best;
  int tripod_finals = 0;                           // runs whose final best is a tripod
};

struct ReproductionSummary {
  std::vector<CaseSummary> cases;          // free, time, performance (those present)
  std::optional<double> case3_over_case1;  // share of generations where case 3's mean best > case 1's
  std::optional<double> case2_over_case1;  // case 2's final mean best / case 1's
  std::optional<EvaluatedSummary> best_biped, best_tripod;
  std::optional<double> biped_over_tripod;  // best biped's fitness / best tripod's
  long evaluations = 0, falls = 0;
  double evaluation_seconds = 0;
};

// The generations (completed) at which best fitness is reported: 500, 1000,
// 2000 (those the runs reached) and the last.
std::vector<int> ReportedGenerations(int generations);

ReproductionSummary Summarize(const std::vector<RunData>& runs);

// The summary with the paper's values beside ours where the paper gives one.
nlohmann::json SummaryToJson(const ReproductionSummary& s);
std::string SummaryToMarkdown(const ReproductionSummary& s, const std::string& title);

// One learner's summary (Summarize of its runs), for the comparison of
// learners under the scaffolds.
struct LearnerSummary {
  std::string learner;  // its name in Learners()
  ReproductionSummary summary;
};

// Per learner and case: the final best fitness over replicates and the runs
// whose final best is a tripod; per learner, the scaffolds' findings (case 3
// against case 1, case 2 against case 1).
nlohmann::json LearnersToJson(const std::vector<LearnerSummary>& learners);
std::string LearnersToMarkdown(const std::vector<LearnerSummary>& learners);

}  // namespace walkers
