// One evolution run in a directory: the generation loop, its files, and
// checkpoints that let a run killed at any moment resume to the same result.
//
// DIR/config.json       everything needed to rerun
// DIR/generations.csv   one row per generation
// DIR/evaluations.csv   one row per evaluation
// DIR/checkpoint.json   the last complete generation (atomic; names the CSVs' sizes)
// DIR/archive.json      the final archive, best first, with fitness
// DIR/best.json         the best genome (a genome file)
// DIR/walkers.lock      locked by the one process writing the run (evolve/files.h)
// DIR/replaced/         while --force replaces a run: the old run's files, until
//                       the new run's first checkpoint is written
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "control/evaluation.h"
#include "control/preset.h"
#include "evolve/files.h"
#include "evolve/genetic_algorithm.h"
#include "evolve/learner.h"
#include "evolve/scaffold.h"

namespace walkers {

constexpr int kMaxGenerations = 10000000;
// Seeds are integers in [0, kMaxSeed].
constexpr std::uint64_t kMaxSeed = 4294967295;

struct RunConfig {
  ScaffoldCase scaffold_case = ScaffoldCase::kFree;
  std::string learner = DefaultLearner().name;  // Learners(): the paper's GA, or another
  Preset preset = OriginalPreset();
  int generations = 4000;
  std::uint64_t seed = 1;
  GeneticAlgorithmConfig ga;  // the GA's settings; its sizes are every learner's
  EvaluationSettings evaluation;

  // Checks every constraint a run needs from its first generation to its
  // last, so that none fails on its configuration once begun. Throws
  // std::invalid_argument naming the field and its allowed range.
  void Validate() const;
};

// config.json's content. "learner" is written only for a learner other than
// the paper's GA, so that the GA's runs keep their files.
nlohmann::json RunConfigToJson(const RunConfig& config);
// config.json's content: every field present, typed and in range, and no
// other. Throws std::runtime_error whose message starts with `source`.
RunConfig RunConfigFromJson(const nlohmann::json& json, const std::string& source);
// The same from the file's text, parsed strictly (control/input_file.h).
RunConfig ParseRunConfig(const std::string& text, const std::string& source);

// What checkpoint.json holds: the run after its last complete generation.
struct Checkpoint {
  int completed_generations = 0;
  double initial_fitness = 0;
  std::uint64_t evaluations_bytes = 0;  // the CSV files' sizes after that generation
  std::uint64_t generations_bytes = 0;
  std::vector<Individual> archive;      // best first
  nlohmann::json learner;               // the learner's state (Learner::State); null for the GA
};

nlohmann::json CheckpointToJson(const Checkpoint& checkpoint);
// Parses a checkpoint of the run configured as `config` (its config.json)
// strictly: every field present, typed and in range; at least one and at most
// config.generations generations; the archive as large as that many
// generations of config.ga fill it, best first, each member's generation and
// child within the run and its genome valid; the learner's state, for a
// learner that keeps one, one that learner restores (Learner::Restore).
// Throws std::runtime_error whose message starts with `source` and names the
// field.
Checkpoint ParseCheckpoint(const std::string& text, const RunConfig& config, const std::string& source);

// archive.json of a finished run configured as `config`, checked as a
// checkpoint's archive is. Throws std::runtime_error naming the file.
std::vector<Individual> LoadArchive(const std::string& path, const RunConfig& config);

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
  kForce,   // replace its run files (nothing else in the directory): the old
            // ones are set aside until the new run's first checkpoint
};

// The file names of a run, inside its directory.
struct RunFiles {
  explicit RunFiles(const std::string& dir);
  std::string dir, config, checkpoint, generations, evaluations, archive, best;

  // every run file above (not dir)
  static const std::vector<std::string RunFiles::*>& All();
  // their names inside dir: "config.json", ...
  static std::vector<std::string> Names();
};

class EvolutionRun {
 public:
  // Validates the configuration, then takes the directory's lock (held until
  // destruction; another process holding it is an error naming its pid), and
  // only then reads or writes anything in it. Throws std::runtime_error with a
  // message naming the directory or file on any problem (holds a run, no run
  // to resume, unwritable, mismatched config, invalid checkpoint or CSV files,
  // a missing checkpoint beside results). Resuming never creates the directory.
  EvolutionRun(const RunConfig& config, const std::string& dir, StartMode mode, int threads);
  // Under kForce, destroyed before the new run's first checkpoint, it puts the
  // old run back.
  ~EvolutionRun();

  // Runs the remaining generations, calling on_generation after each (the
  // checkpoint is on disk by then); then writes archive.json and best.json.
  void Run(const std::function<void(const GenerationSummary&)>& on_generation = nullptr);

  int completed_generations() const { return completed_; }
  const Archive& archive() const { return archive_; }
  const Learner& learner() const { return *learner_; }
  double initial_fitness() const { return initial_fitness_; }
  const RunFiles& files() const { return files_; }

 private:
  void StartFresh();
  void Resume();
  void CheckNoResultsWithoutCheckpoint() const;
  void WriteCheckpoint(std::uint64_t evaluations_bytes, std::uint64_t generations_bytes);
  void WriteResults();

  RunConfig config_;
  RunFiles files_;
  std::optional<FolderLock> lock_;
  std::unique_ptr<SetAside> replaced_;  // under kForce, until the first checkpoint
  int threads_;
  std::unique_ptr<Scaffold> scaffold_;
  std::unique_ptr<Learner> learner_;
  Archive archive_;
  std::set<GenomeKey> seen_;
  double initial_fitness_ = kAuthorsInitialFitness;
  int completed_ = 0;
};

// The CSV headers, for readers of the files.
extern const char* const kGenerationsHeader;
std::string EvaluationsHeader();

}  // namespace walkers
