// A run's configuration, config.json's content, and what one generation did:
// what EvolutionRun (evolve/run.h) is given and reports. The configuration
// is checked whole before a run touches its folder (RunConfig::Validate).
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "control/evaluation.h"
#include "control/preset.h"
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
  // InputError naming `source` (the file, when the configuration comes from
  // one), the field and its allowed range.
  void Validate(const std::string& source = "") const;
};

// config.json's content. "learner" is written only for a learner other than
// the paper's GA, so that the GA's runs keep their files.
nlohmann::json RunConfigToJson(const RunConfig& config);
// The evaluation settings as config.json's "evaluation" object records them.
nlohmann::json EvaluationSettingsToJson(const EvaluationSettings& settings);
// Throws InputError naming `source` and the first setting in which the
// run `stored` (its config.json) differs from `requested`, its learner
// included; the generations may differ (a resumed run may be extended).
void RequireResumableAs(const RunConfig& stored, const RunConfig& requested, const std::string& source);
// config.json's content: every field present, typed and in range, and no
// other. Throws InputError whose message starts with `source`.
RunConfig RunConfigFromJson(const nlohmann::json& json, const std::string& source);
// The same from the file's text, parsed strictly (files/input_file.h).
RunConfig ParseRunConfig(const std::string& text, const std::string& source);
// Whether the run's files name its learner: only one other than the paper's
// GA, so that the GA's runs keep their files.
bool NamesLearner(const RunConfig& config);

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

}  // namespace walkers
