// A reproduction of the paper's results: the three scaffolds, each with
// several replicate runs of each learner, then what the statistics and the
// figures need of the simulator.
//
// DIR/<case>-<replicate>/   one evolution run each (evolve/run.h) of the GA;
// DIR/<learner>-<case>-<replicate>/  of another learner (evolve/learner.h)
// DIR/reproduction.json     the configuration, the cases and learners, and every
//                           run's finals with their re-scores (evolve/finals.h)
// DIR/rescores.json         the re-scores' cache, by genome
// DIR/walks.json            the best biped's and best tripod's walks (control/walk_record.h)
// DIR/gallery.json          every run's final best and, if that is a biped, its
//                           best tripod, standing, to scale
// DIR/summary.json          the statistics and the claims' verdicts, and
// DIR/summary.md            the same as tables a person reads: written from the
//                           files above by scripts/walkers_stats (app/statistics.h)
// DIR/figures/              drawn by scripts/walkers_stats too
// DIR/walkers.lock          locked by the one process writing the reproduction
// DIR/replaced/             while --force replaces a reproduction: the old one,
//                           until the new first run's first checkpoint is written
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "control/evaluation.h"
#include "control/preset.h"
#include "evolve/evaluator.h"
#include "evolve/finals.h"
#include "evolve/genetic_algorithm.h"
#include "evolve/run.h"
#include "files/results_folder.h"

namespace walkers {

constexpr int kMaxReplicates = 1000;

struct ReproductionConfig {
  // the learners compared, each under every scaffold; the first is the one
  // the paper's statistics and figures 4-9 show
  std::vector<std::string> learners = {DefaultLearner().name};
  Preset preset = OriginalPreset();
  int generations = 4000;
  int replicates = 3;
  std::uint64_t seed = 1;  // replicate r of every case runs with seed + r - 1
  GeneticAlgorithmConfig ga;
  EvaluationSettings evaluation;
  int ensemble = 25;  // members of each final's re-score (evolve/finals.h)

  // Every run's configuration (RunConfig::Validate), seed + replicates - 1
  // within the seeds' range, at least one learner, none twice, and the
  // ensemble's size in [1, kMaxEnsemble]. Throws InputError naming the
  // field.
  void Validate() const;
};

// The files of a reproduction's results, inside its directory.
struct ReproductionFiles {
  explicit ReproductionFiles(const std::string& dir);
  std::string manifest, rescores, walks, gallery, summary_json, summary_md, figures;

  // their names inside the directory
  static std::vector<std::string> Names();
};

struct PlannedRun {
  ScaffoldCase scaffold_case;
  int replicate;
  std::string name;  // "<case>-<replicate>" for the GA, "<learner>-<case>-<replicate>" for another
  RunConfig config;  // its learner too
};

std::vector<PlannedRun> PlanRuns(const ReproductionConfig& config);

// The order in which a reproduction starts the runs of its plan, as indices
// into it: replicate by replicate, every learner's and case's replicate r
// before any replicate r + 1, so that the runs finished at any moment form a
// balanced design (3 x 3, then 3 x 4, ...).
std::vector<std::size_t> StartOrder(const std::vector<PlannedRun>& plan);

// The scaffolds as reproduction.json lists them for the statistics: name,
// label, colour and the paper's tripods of each, in the paper's order.
nlohmann::json ScaffoldsJson();
// The reproduction's learners, likewise, in the order given.
nlohmann::json LearnersJson(const std::vector<std::string>& learners);

// Called before each run starts (with how many generations it has done) and
// after each of its generations; with runs side by side, from their threads,
// one call at a time. Then, while the finals are re-scored, after each batch
// of genomes (how many are done of those that were not in the cache).
struct ReproductionObserver {
  std::function<void(const PlannedRun&, int completed_generations)> on_run_start;
  std::function<void(const PlannedRun&, const GenerationSummary&)> on_generation;
  std::function<void(int done, int needed)> on_rescore;
};

// A reproduction in a directory. It holds the directory's lock from
// construction to destruction: keep it while the figures are drawn.
class Reproduction {
 public:
  // Validates the configuration, then takes the directory's lock and only
  // then looks inside. kNew refuses a directory that holds any runs or
  // results of a reproduction; kResume needs the directory (it continues
  // unfinished runs, skips finished ones and starts missing ones); kForce
  // sets the old runs and results aside in DIR/replaced/ until the first new
  // run's first checkpoint, and puts them back if abandoned before it.
  // Throws InputError for a configuration that cannot run, std::runtime_error
  // for a folder that cannot be written as asked; each names the directory.
  Reproduction(const ReproductionConfig& config, const std::string& dir, StartMode mode);
  ~Reproduction();

  // Runs (or resumes) every run, `runs_at_once` of them side by side, their
  // evaluations on `evaluator`, each writing its finals.json (WriteRunFinals)
  // as it finishes; then WriteReproductionData. A finished run kept without
  // its evaluations (KeptWithoutEvaluations) counts as done. The files do not
  // depend on the evaluator or on runs_at_once. When a run fails, the others
  // stop after their generation under way and its error is thrown.
  void Run(Evaluator& evaluator, const ReproductionObserver& observer = {}, int runs_at_once = 1);

 private:
  ReproductionConfig config_;
  std::string dir_;
  std::vector<PlannedRun> plan_;
  std::optional<ResultsFolder> folder_;  // its lock; under kForce, the old one set aside
};

// After the runs: reads every finished run's finals in DIR, re-scores them on
// `evaluator` (those not in DIR/rescores.json already), and writes
// reproduction.json, walks.json (the first learner's best biped and best
// tripod by their re-scores' medians) and gallery.json.
void WriteReproductionData(const ReproductionConfig& config, const std::string& dir, Evaluator& evaluator,
                           const std::function<void(int done, int needed)>& on_rescore = nullptr);

}  // namespace walkers
