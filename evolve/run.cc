#include "evolve/run.h"

#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "files/durable_file.h"
#include "files/errors.h"
#include "files/input_file.h"

namespace walkers {
namespace fs = std::filesystem;
using nlohmann::json;

EvolutionRun::EvolutionRun(const RunConfig& config, const std::string& dir, StartMode mode, Evaluator& evaluator,
                           std::unique_ptr<Learner> learner)
    : config_(config), files_(dir), evaluator_(&evaluator), archive_(config.ga.archive_size) {
  // the whole configuration first: nothing is touched for one that cannot run
  config_.Validate();
  scaffold_ = MakeScaffold(config.scaffold_case, config.preset);
  WALKERS_CHECK(!learner || learner->spec().name == config.learner,
                "the learner given is " + std::string(learner->spec().name) + ", not the run's (" + config.learner +
                    ")");
  learner_ = learner ? std::move(learner) : MakeLearner(config.learner, config.ga, config.seed);
  folder_.emplace(dir, "run", mode, files_.checkpoint, [&] {
    FolderContents held{RunFiles::Names(), "", false};
    for (auto file : RunFiles::All()) held.any = held.any || fs::exists(files_.*file);
    return held;
  });
  if (mode == StartMode::kResume) {
    if (!fs::exists(files_.config)) throw std::runtime_error(dir + ": no run to resume (config.json is missing)");
    Resume();
  } else {
    StartFresh();
  }
}

// folder_ goes first, while the learner and the files are still there
EvolutionRun::~EvolutionRun() = default;

void EvolutionRun::StartFresh() {
  WriteFileAtomically(files_.config, RunConfigToJson(config_).dump(2) + "\n");
  WriteFileAtomically(files_.generations, std::string(kGenerationsHeader) + "\n");
  WriteFileAtomically(files_.evaluations, EvaluationsHeader() + "\n");
  completed_ = 0;
}

void EvolutionRun::Resume() {
  // everything is read and checked before anything is written
  const RunConfig stored = RunConfigFromJson(LoadJsonFile(files_.config), files_.config);
  RequireResumableAs(stored, config_, files_.config);
  if (!fs::exists(files_.checkpoint)) {
    // killed before its first generation completed: start it again
    CheckNoResultsWithoutCheckpoint(files_, config_);
    StartFresh();
    return;
  }
  Checkpoint cp = ParseCheckpoint(ReadFile(files_.checkpoint), stored, files_.checkpoint);
  if (cp.completed_generations > config_.generations) {
    throw InputError(files_.dir + ": the run has " + std::to_string(cp.completed_generations) +
                     " generations already, more than the " + std::to_string(config_.generations) + " asked for");
  }
  std::set<GenomeKey> seen = CheckRunFilesUpTo(files_, cp, stored);

  completed_ = cp.completed_generations;
  initial_fitness_ = cp.initial_fitness;
  archive_.Restore(std::move(cp.archive));
  if (learner_->KeepsState()) learner_->Restore(cp.learner, cp.completed_generations, files_.checkpoint);
  seen_ = std::move(seen);
  // drop what was written after the checkpoint
  TruncateFile(files_.evaluations, cp.evaluations_bytes);
  TruncateFile(files_.generations, cp.generations_bytes);
  // a longer run than first asked for: the config says so from now on
  WriteFileAtomically(files_.config, RunConfigToJson(config_).dump(2) + "\n");
  // killed after its last checkpoint, before its results were written
  if (done()) WriteResults();
}

void EvolutionRun::Run(const std::function<void(const GenerationSummary&)>& on_generation) {
  while (!done()) {
    const BreedingInputs in = BeginGeneration();
    const EvaluatedChildren evaluated = EvaluateChildren(in, learner_->Propose(in, archive_));
    learner_->Tell(in, evaluated.children);
    const GenerationSummary summary = FinishGeneration(in, evaluated, learner_->State());
    if (on_generation) on_generation(summary);
  }
}

BreedingInputs EvolutionRun::BeginGeneration() const {
  const int g = completed_;
  WALKERS_CHECK(!done(), "generation " + std::to_string(g) + " begun; the run has " +
                             std::to_string(config_.generations));
  BreedingInputs in;
  in.seed = config_.seed;
  in.generation = g;
  // the scaffold sets this generation's ceiling from what the archive
  // achieved so far; the authors' evolver starts that measure at InitF
  const double achieved = g == 0 ? initial_fitness_ : archive_.AverageOfBest(3);
  in.body_ceiling = scaffold_->Ceiling({g, achieved, initial_fitness_});
  in.rules.probability = config_.ga.mutation_probability;
  in.rules.body_gene = config_.preset.body_gene_mutation;
  in.rules.body_redraw = ScaffoldSpecOf(config_.scaffold_case).authors_body_redraw;
  return in;
}

EvaluatedChildren EvolutionRun::EvaluateChildren(const BreedingInputs& in, std::vector<Individual> proposals) {
  WALKERS_CHECK(in.generation == completed_, "generation " + std::to_string(in.generation) +
                                                 " evaluated after " + std::to_string(completed_) + " completed");
  // the GA's rules admit the proposals (clamped into the bounds, duplicates
  // drawn again)
  EvaluatedChildren out{std::move(proposals), 0.0};
  AdmitChildren(*learner_, in, &out.children, &seen_);
  // the costly children first, so the generation waits less for its slowest
  std::vector<double> expected_costs;
  for (const Individual& c : out.children) expected_costs.push_back(ExpectedCost(c, archive_));
  const auto start = std::chrono::steady_clock::now();
  EvaluateIndividuals(*evaluator_, &out.children, config_.preset, config_.evaluation, expected_costs);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

GenerationSummary EvolutionRun::FinishGeneration(const BreedingInputs& in, const EvaluatedChildren& evaluated,
                                                 const json& learner_state) {
  const std::vector<Individual>& children = evaluated.children;
  WALKERS_CHECK(in.generation == completed_, "generation " + std::to_string(in.generation) +
                                                 " finished after " + std::to_string(completed_) + " completed");
  archive_.Merge(children);

  GenerationSummary s;
  s.generation = in.generation;
  s.generations = config_.generations;
  s.best_fitness = archive_.best().fitness();
  s.ave_best3 = archive_.AverageOfBest(3);
  s.archive_mean = archive_.Mean();
  s.ceiling = in.body_ceiling;
  s.best_half_body_x = archive_.best().genome[kHalfBodyX];
  s.best_femur = archive_.best().genome[kFemurLength];
  s.best_tibia = archive_.best().genome[kTibiaLength];
  s.best_gait = archive_.best().result.gait;
  for (const Individual& c : children) s.falls += c.result.outcome == Outcome::kFell ? 1 : 0;
  s.evaluations = static_cast<int>(children.size());
  s.evaluation_seconds = evaluated.seconds;
  s.evals_per_s = evaluated.seconds > 0 ? children.size() / evaluated.seconds : 0.0;

  // the rows reach the disk first; the checkpoint then names them
  std::string rows;
  for (const Individual& c : children) rows += EvaluationRow(c);
  const std::uint64_t evaluations_bytes = AppendDurably(files_.evaluations, rows);
  const std::uint64_t generations_bytes = AppendDurably(files_.generations, GenerationRow(s));
  completed_ = in.generation + 1;
  const Checkpoint cp{completed_,          initial_fitness_, evaluations_bytes, generations_bytes, archive_.members(),
                      learner_state};
  WriteFileAtomically(files_.checkpoint, CheckpointToJson(cp).dump() + "\n");
  folder_->DiscardReplaced();  // the new run has its first checkpoint
  if (done()) WriteResults();
  return s;
}

void EvolutionRun::WriteResults() {
  const json out = ArchiveFileJson(config_, completed_, initial_fitness_, archive_.members());
  WriteFileAtomically(files_.archive, out.dump(2) + "\n");
  SaveGenome(archive_.best().genome, files_.best);
}

}  // namespace walkers
