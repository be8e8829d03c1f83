// One evolution run in a directory: the generation loop, and checkpoints that
// let a run killed at any moment resume to the same result. Its configuration
// and the summary of a generation are evolve/run_config.h's; its files and
// their formats evolve/run_files.h's; what its evaluations run on is the
// Evaluator given (evolve/evaluator.h); its folder's lock and --force's
// set-aside are files/results_folder.h's.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "evolve/evaluator.h"
#include "evolve/learner.h"
#include "evolve/run_config.h"
#include "evolve/run_files.h"
#include "evolve/scaffold.h"
#include "files/results_folder.h"

namespace walkers {

class EvolutionRun {
 public:
  // Validates the configuration, then takes the directory's lock (held until
  // destruction; another process holding it is an error naming its pid), and
  // only then reads or writes anything in it (ResultsFolder). Throws std::runtime_error with a
  // message naming the directory or file on any problem (holds a run, no run
  // to resume, unwritable, mismatched config, invalid checkpoint or CSV files,
  // a missing checkpoint beside results). Resuming never creates the directory.
  // The evaluator must outlive the run. `learner`, when given, is the learner
  // to run (one of config.learner's kind, an ExternalLearner with its source,
  // say); by default MakeLearner's.
  EvolutionRun(const RunConfig& config, const std::string& dir, StartMode mode, Evaluator& evaluator,
               std::unique_ptr<Learner> learner = nullptr);
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
  void WriteCheckpoint(std::uint64_t evaluations_bytes, std::uint64_t generations_bytes);
  void WriteResults();

  RunConfig config_;
  RunFiles files_;
  std::optional<ResultsFolder> folder_;
  Evaluator* evaluator_;
  std::unique_ptr<Scaffold> scaffold_;
  std::unique_ptr<Learner> learner_;
  Archive archive_;
  std::set<GenomeKey> seen_;
  double initial_fitness_ = kAuthorsInitialFitness;
  int completed_ = 0;
};

}  // namespace walkers
