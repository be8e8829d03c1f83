// One evolution run in a directory: its generations, each in two halves that
// the caller drives, and checkpoints that let a run killed at any moment
// resume to the same result. Its configuration and the summary of a
// generation are evolve/run_config.h's; its files and their formats
// evolve/run_files.h's; its folder's lock and --force's set-aside
// files/results_folder.h's; what its evaluations run on is the Evaluator
// given (evolve/evaluator.h).
//
// A generation, as Run() drives it with the run's own learner, and as the
// Python module's walkers.Run drives it with an optimiser in Python:
//   in = BeginGeneration()                the scaffold's ceiling: the children's
//                                         bounds (ChildGeneBounds) and what the
//                                         learner is asked (Learner::Propose)
//   children = EvaluateChildren(in, proposals)   the GA's rules, then evaluation
//   FinishGeneration(in, children, state)        the archive, the files, the
//                                         checkpoint with the learner's state
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/evaluator.h"
#include "evolve/learner.h"
#include "evolve/run_config.h"
#include "evolve/run_files.h"
#include "evolve/scaffold.h"
#include "files/results_folder.h"

namespace walkers {

// A generation's children as the run evaluated them.
struct EvaluatedChildren {
  std::vector<Individual> children;  // in the order proposed, after the GA's rules
  double seconds = 0;                // the wall time their evaluations took
};

class EvolutionRun {
 public:
  // Validates the configuration, then takes the directory's lock (held until
  // destruction; another process holding it is an error naming its pid), and
  // only then reads or writes anything in it (ResultsFolder). Throws
  // InputError for a configuration or files that cannot be run or resumed
  // (mismatched config, invalid checkpoint or CSV files, a missing checkpoint
  // beside results), std::runtime_error for a folder that holds a run, has
  // none to resume or cannot be written; each message names the directory or
  // file. Resuming never creates the directory; resuming a run whose
  // generations are all done writes its archive.json and best.json again.
  // The evaluator must outlive the run. `learner`, when given, is the learner
  // to run (one of config.learner's kind); by default MakeLearner's.
  EvolutionRun(const RunConfig& config, const std::string& dir, StartMode mode, Evaluator& evaluator,
               std::unique_ptr<Learner> learner = nullptr);
  // Under kForce, destroyed before the new run's first checkpoint, it puts the
  // old run back.
  ~EvolutionRun();

  // Runs the remaining generations with the run's learner, calling
  // on_generation after each (its checkpoint is on disk by then).
  void Run(const std::function<void(const GenerationSummary&)>& on_generation = nullptr);

  // The first half of generation completed_generations(): the scaffold's
  // ceiling on halfBodyX from what the archive achieved so far, which sets
  // the children's bounds (ChildGeneBounds(gene, in.body_ceiling)), and the
  // rest of what its learner is asked. The run is unchanged.
  BreedingInputs BeginGeneration() const;
  // The generation's proposals (in order, each with its generation, child and
  // lineage) under the GA's rules (AdmitChildren: clamped, a genome seen before
  // drawn again by the run's learner), then evaluated on the run's evaluator,
  // the costly first. Throws what AdmitChildren throws.
  EvaluatedChildren EvaluateChildren(const BreedingInputs& in, std::vector<Individual> proposals);
  // The second half: the evaluated children join the archive, their rows and
  // the generation's reach the disk, then the checkpoint, holding
  // `learner_state` (the learner's Learner::State() after it was told them).
  // After the last generation, archive.json and best.json are written.
  // Returns what the generation did.
  GenerationSummary FinishGeneration(const BreedingInputs& in, const EvaluatedChildren& evaluated,
                                     const nlohmann::json& learner_state);

  bool done() const { return completed_ >= config_.generations; }
  int completed_generations() const { return completed_; }
  const RunConfig& config() const { return config_; }
  const Archive& archive() const { return archive_; }
  const Learner& learner() const { return *learner_; }
  double initial_fitness() const { return initial_fitness_; }
  const RunFiles& files() const { return files_; }

 private:
  void StartFresh();
  void Resume();
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
