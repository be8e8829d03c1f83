// One evolution run in a directory: the generation loop, its files, and
// checkpoints that let a run killed at any moment resume to the same result.
//
// DIR/config.json       everything needed to rerun
// DIR/generations.csv   one row per generation
// DIR/evaluations.csv   one row per evaluation
// DIR/checkpoint.json   the last complete generation (atomic; names the CSVs' sizes)
// DIR/archive.json      the final archive, best first, with fitness
// DIR/best.json         the best genome (a genome file)
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "control/evaluation.h"
#include "control/preset.h"
#include "evolve/genetic_algorithm.h"
#include "evolve/scaffold.h"

namespace walkers {

struct RunConfig {
  ScaffoldCase scaffold_case = ScaffoldCase::kFree;
  Preset preset = OriginalPreset();
  int generations = 4000;
  std::uint64_t seed = 1;
  GeneticAlgorithmConfig ga;
  EvaluationSettings evaluation;

  // Throws std::invalid_argument naming the field and its allowed range.
  void Validate() const;
};

nlohmann::json RunConfigToJson(const RunConfig& config);
// `source` names the file in error messages.
RunConfig RunConfigFromJson(const nlohmann::json& json, const std::string& source);

// What one generation did, for progress reports and generations.csv.
struct GenerationSummary {
  int generation = 0;
  int generations = 0;          // of the run
  double best_fitness = 0;      // archive's best after this generation
  double ave_best3 = 0;
  double archive_mean = 0;
  double ceiling = 0;           // halfBodyX ceiling this generation's children had
  double best_half_body_x = 0;
  double best_femur = 0;
  double best_tibia = 0;
  Gait best_gait = Gait::kBiped;
  int falls = 0;                // children that fell
  int evaluations = 0;
  double evaluation_seconds = 0;  // wall time of this generation's evaluations
  double evals_per_s = 0;
};

enum class StartMode {
  kNew,     // refuse a directory that holds a run
  kResume,  // continue it from its last checkpoint (its config must match)
  kForce,   // replace its run files (nothing else in the directory)
};

// The file names of a run, inside its directory.
struct RunFiles {
  explicit RunFiles(const std::string& dir);
  std::string dir, config, checkpoint, generations, evaluations, archive, best;
};

class EvolutionRun {
 public:
  // Prepares the directory. Throws std::runtime_error with a message naming
  // the directory or file on any problem (exists, unwritable, mismatched
  // config, corrupt checkpoint).
  EvolutionRun(const RunConfig& config, const std::string& dir, StartMode mode, int threads);
  ~EvolutionRun();

  // Runs the remaining generations, calling on_generation after each; then
  // writes archive.json and best.json.
  void Run(const std::function<void(const GenerationSummary&)>& on_generation = nullptr);

  int completed_generations() const { return completed_; }
  const Archive& archive() const { return archive_; }
  double initial_fitness() const { return initial_fitness_; }
  const RunFiles& files() const { return files_; }

 private:
  void StartFresh();
  void Resume();
  void WriteCheckpoint(std::uint64_t evaluations_bytes, std::uint64_t generations_bytes);
  void WriteResults();

  RunConfig config_;
  RunFiles files_;
  int threads_;
  std::unique_ptr<Scaffold> scaffold_;
  Archive archive_;
  std::set<GenomeKey> seen_;
  double initial_fitness_ = kAuthorsInitialFitness;
  int completed_ = 0;
};

// The CSV headers, for readers of the files.
extern const char* const kGenerationsHeader;
std::string EvaluationsHeader();

}  // namespace walkers
