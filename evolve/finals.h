// A run's finals (paper §3): its final best, and the best biped and the best
// tripod of all its evaluations, each evaluated again by an ensemble of
// perturbed evaluations (control/accuracy.h). The walk can be chaotic, so the
// fitness a run recorded is one draw; the claims about final fitness use the
// ensembles' medians (docs/statistics.md). The statistics themselves are the
// Python package's (scripts/walkers_stats/); this is what needs the simulator.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "control/accuracy.h"
#include "evolve/evaluator.h"
#include "evolve/individual.h"
#include "evolve/run_files.h"
#include "evolve/variation.h"

namespace walkers {

// The largest ensemble a genome is evaluated by (walkers evaluate --ensemble,
// walkers reproduce --ensemble).
constexpr int kMaxEnsemble = 1000;

struct RunFinals {
  Individual final_best;                              // the archive's best at the end (archive.json)
  std::optional<Individual> best_biped, best_tripod;  // over every evaluation that did not fall
};

// Reads DIR/archive.json and DIR/evaluations.csv of the run configured as
// `config`. Every generation in evaluations.csv must hold the run's population
// of children: the statistics count a run's evaluations as population x
// generations. A finished run kept without its evaluations.csv (committed
// results leave the per-evaluation data out) is read from DIR/finals.json,
// which WriteRunFinals wrote. Throws InputError naming the file.
RunFinals LoadRunFinals(const std::string& dir, const RunConfig& config);

// Writes DIR/finals.json: the finished run's best biped and best tripod, read
// from its evaluations, so that its statistics can be made again without them.
void WriteRunFinals(const std::string& dir, const RunConfig& config, const RunFinals& finals);

// Whether DIR holds a finished run kept without its evaluations.csv (and with
// its finals.json): a run whose statistics can be made, but which cannot be
// continued. Throws InputError naming the file when the run's
// config.json is not `config`, or when it has not finished `config`'s
// generations.
bool KeptWithoutEvaluations(const std::string& dir, const RunConfig& config);

// Ensembles of genomes at one preset, evaluation settings and ensemble size,
// kept in a JSON file by genome, so that a reproduction resumed after its runs
// have finished evaluates none again.
class RescoreCache {
 public:
  // Reads `path` when it exists and holds ensembles of the same preset,
  // settings and size; else (or when absent) starts empty. Throws
  // InputError naming the file, the field and how to do without the file
  // when it is malformed.
  RescoreCache(std::string path, const Preset& preset, const EvaluationSettings& settings, int size);

  // the ensemble of a genome; nullptr when it has none
  const FitnessEnsemble* Find(const Genome& genome) const;

  // Evaluates the genomes without an ensemble (their members on the
  // evaluator, `per_write` genomes at a time, the file written after each
  // such batch, so that an interruption loses at most one batch), then keeps
  // only `genomes` in the file. `on_batch` is told how many genomes are done
  // and how many needed evaluating.
  void Rescore(const std::vector<Genome>& genomes, Evaluator& evaluator, int per_write,
               const std::function<void(int done, int needed)>& on_batch = nullptr);

  int size() const { return size_; }

 private:
  void Write() const;

  std::string path_;
  Preset preset_;
  EvaluationSettings settings_;
  int size_;
  std::map<GenomeKey, std::pair<Genome, FitnessEnsemble>> entries_;
};

// An ensemble for the statistics: {"fitness": [...], "median", "min", "max",
// "bipeds", "tripods", "falls", "recorded_reproduced"}; the last says whether
// the unperturbed middle member (odd sizes only; else null) scored `recorded`
// exactly, as the same build must.
nlohmann::json RescoreJson(const FitnessEnsemble& ensemble, double recorded);

}  // namespace walkers
