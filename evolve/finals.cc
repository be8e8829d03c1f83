#include "evolve/finals.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "files/csv.h"
#include "files/durable_file.h"
#include "files/input_file.h"

namespace walkers {
namespace {

using nlohmann::json;

// A best biped or tripod in finals.json: where it came from, its fitness and
// gait, its genome; null when the run evaluated none.
json FinalistToJson(const std::optional<Individual>& finalist) {
  if (!finalist) return nullptr;
  return {{"id", finalist->id()},
          {"generation", finalist->generation},
          {"child", finalist->child},
          {"fitness", finalist->fitness()},
          {"gait", GaitName(finalist->result.gait)},
          {"genome", GenomeToJson(finalist->genome)}};
}

std::optional<Individual> FinalistFromJson(const JsonFields& f, const std::string& key, Gait gait,
                                           const RunConfig& config) {
  if (f.Get(key).is_null()) return std::nullopt;
  const JsonFields e = f.Object(key);
  e.RequireOnly({"id", "generation", "child", "fitness", "gait", "genome"});
  Individual finalist;
  finalist.generation = static_cast<int>(e.Integer("generation", 0, config.generations - 1));
  finalist.child = static_cast<int>(e.Integer("child", 0, config.ga.population - 1));
  if (e.String("id") != finalist.id()) e.Fail("id", "is not \"" + finalist.id() + "\", its generation and child");
  finalist.result.fitness = e.Number("fitness");
  if (e.String("gait") != GaitName(gait)) e.Fail("gait", "is not '" + std::string(GaitName(gait)) + "'");
  finalist.result.gait = gait;
  finalist.genome = GenomeFromJson(e.Get("genome"), f.source() + ": " + e.Name("genome"));
  return finalist;
}

// a run kept with its finals.json but without its evaluations.csv
bool FinalsOnly(const RunFiles& files) {
  return !std::filesystem::exists(files.evaluations) && std::filesystem::exists(files.finals);
}

// DIR/finals.json of a run that finished config.generations
RunFinals ReadFinalsFile(const RunFiles& files, const RunConfig& config, const Individual& final_best) {
  const json j = LoadJsonFile(files.finals);
  const JsonFields f(j, files.finals);
  f.RequireOnly({"generations", "best_biped", "best_tripod"});
  f.Integer("generations", config.generations, config.generations);
  return {final_best, FinalistFromJson(f, "best_biped", Gait::kBiped, config),
          FinalistFromJson(f, "best_tripod", Gait::kTripod, config)};
}

}  // namespace

void WriteRunFinals(const std::string& dir, const RunConfig& config, const RunFinals& finals) {
  const json out = {{"generations", config.generations},
                    {"best_biped", FinalistToJson(finals.best_biped)},
                    {"best_tripod", FinalistToJson(finals.best_tripod)}};
  WriteFileAtomically(RunFiles(dir).finals, out.dump(2) + "\n");
}

bool KeptWithoutEvaluations(const std::string& dir, const RunConfig& config) {
  const RunFiles files(dir);
  if (!FinalsOnly(files)) return false;
  const RunConfig stored = RunConfigFromJson(LoadJsonFile(files.config), files.config);
  RequireResumableAs(stored, config, files.config);  // a longer run asked for is refused below, by name
  const Checkpoint cp = ParseCheckpoint(ReadFile(files.checkpoint), stored, files.checkpoint);
  if (cp.completed_generations != config.generations) {
    throw InputError(files.dir + ": the run has " + std::to_string(cp.completed_generations) + " of " +
                     std::to_string(config.generations) +
                     " generations and no evaluations.csv: it cannot be continued without them");
  }
  return true;
}

RunFinals LoadRunFinals(const std::string& dir, const RunConfig& config) {
  const RunFiles files(dir);
  RunFinals finals{LoadArchive(files.archive, config).front(), std::nullopt, std::nullopt};
  if (FinalsOnly(files)) return ReadFinalsFile(files, config, finals.final_best);

  CsvReader rows(ReadFile(files.evaluations), files.evaluations);
  const int generation = rows.Column("generation");
  const int child = rows.Column("child");
  const int fitness = rows.Column("fitness");
  const int fell = rows.Column("fell");
  const int gait = rows.Column("gait");
  const int first_gene = rows.Column(GeneTable()[0].name);
  std::vector<int> per_generation;
  while (rows.Next()) {
    const std::vector<std::string>& row = rows.fields();
    const auto g = static_cast<std::size_t>(rows.Integer(generation, 0, config.generations - 1));
    if (g >= per_generation.size()) per_generation.resize(g + 1, 0);
    ++per_generation[g];
    if (row[fell] == "1") continue;
    // the first of the fittest of its class
    std::optional<Individual>& kept = row[gait] == "tripod" ? finals.best_tripod : finals.best_biped;
    const double f = rows.Number(fitness);
    if (kept && kept->fitness() >= f) continue;
    Individual e;
    e.generation = static_cast<int>(g);
    e.child = static_cast<int>(rows.Integer(child, 0, std::numeric_limits<int>::max()));
    e.result.fitness = f;
    e.result.gait = row[gait] == "tripod" ? Gait::kTripod : Gait::kBiped;
    e.genome = DefaultGenome();
    for (int k = 0; k < kNumGenes; ++k) e.genome.genes[k] = rows.Number(first_gene + k);
    kept = e;
  }
  for (std::size_t g = 0; g < per_generation.size(); ++g) {
    if (per_generation[g] != config.ga.population) {
      throw InputError(files.evaluations + ": generation " + std::to_string(g) + " has " +
                       std::to_string(per_generation[g]) + " evaluations, not the population's " +
                       std::to_string(config.ga.population));
    }
  }
  return finals;
}

RescoreCache::RescoreCache(std::string path, const Preset& preset, const EvaluationSettings& settings, int size)
    : path_(std::move(path)), preset_(preset), settings_(settings), size_(size) {
  if (!std::filesystem::exists(path_)) return;
  // its messages say what it is, and how to do without it
  const std::string source = path_ + " (a cache of re-scores: remove it to evaluate them again)";
  const json j = ParseJson(ReadFile(path_), source);
  const JsonFields f(j, source);
  f.RequireOnly({"preset", "evaluation", "ensemble", "genomes"});
  // another preset, other settings or another size: none of its ensembles is of use
  if (f.String("preset") != preset_.name || f.Get("evaluation") != EvaluationSettingsToJson(settings_) ||
      f.Integer("ensemble", 1, kMaxEnsemble) != size_) {
    return;
  }
  const json& genomes = f.Array("genomes");
  for (std::size_t i = 0; i < genomes.size(); ++i) {
    const JsonFields e(genomes[i], source, "genomes[" + std::to_string(i) + "].");
    e.RequireOnly({"genome", "fitness", "bipeds", "tripods", "falls"});
    const Genome genome = GenomeFromJson(e.Get("genome"), source + ": " + e.Name("genome"));
    FitnessEnsemble ensemble;
    const json& fitness = e.Array("fitness");
    if (fitness.size() != static_cast<std::size_t>(size_)) e.Fail("fitness", "does not hold " + std::to_string(size_) + " members");
    for (const json& x : fitness) {
      if (!x.is_number() || !std::isfinite(x.get<double>())) e.Fail("fitness", "holds a member that is not a finite number");
      ensemble.fitness.push_back(x.get<double>());
    }
    ensemble.bipeds = static_cast<int>(e.Integer("bipeds", 0, size_));
    ensemble.tripods = static_cast<int>(e.Integer("tripods", 0, size_));
    ensemble.falls = static_cast<int>(e.Integer("falls", 0, size_));
    entries_[KeyOf(genome)] = {genome, ensemble};
  }
}

const FitnessEnsemble* RescoreCache::Find(const Genome& genome) const {
  const auto it = entries_.find(KeyOf(genome));
  return it == entries_.end() ? nullptr : &it->second.second;
}

void RescoreCache::Rescore(const std::vector<Genome>& genomes, Evaluator& evaluator, int per_write,
                           const std::function<void(int done, int needed)>& on_batch) {
  // the genomes to evaluate, each once
  std::vector<Genome> needed;
  std::set<GenomeKey> wanted;
  for (const Genome& g : genomes) {
    if (wanted.insert(KeyOf(g)).second && !Find(g)) needed.push_back(g);
  }
  std::vector<EvaluationSettings> members;
  for (int k = 0; k < size_; ++k) members.push_back(EnsembleMemberSettings(settings_, size_, k));
  const std::size_t step = static_cast<std::size_t>(std::max(1, per_write));
  for (std::size_t first = 0; first < needed.size(); first += step) {
    const std::size_t last = std::min(needed.size(), first + step);
    std::vector<EvaluationResult> results((last - first) * size_);
    std::vector<EvaluationTask> tasks;
    for (std::size_t i = first; i < last; ++i) {
      for (int k = 0; k < size_; ++k) {
        tasks.push_back({&needed[i], &preset_, &members[k], &results[(i - first) * size_ + k], 0.0});
      }
    }
    evaluator.EvaluateAll(tasks);
    for (std::size_t i = first; i < last; ++i) {
      const auto begin = results.begin() + static_cast<std::ptrdiff_t>((i - first) * size_);
      entries_[KeyOf(needed[i])] = {needed[i], EnsembleOf({begin, begin + size_})};
    }
    Write();
    if (on_batch) on_batch(static_cast<int>(last), static_cast<int>(needed.size()));
  }
  // the file keeps the ensembles of these genomes only
  for (auto it = entries_.begin(); it != entries_.end();) {
    it = wanted.count(it->first) ? std::next(it) : entries_.erase(it);
  }
  Write();
}

void RescoreCache::Write() const {
  json genomes = json::array();
  for (const auto& [key, entry] : entries_) {
    const FitnessEnsemble& e = entry.second;
    genomes.push_back({{"genome", GenomeToJson(entry.first)},
                       {"fitness", e.fitness},
                       {"bipeds", e.bipeds},
                       {"tripods", e.tripods},
                       {"falls", e.falls}});
  }
  const json out = {
      {"preset", preset_.name}, {"evaluation", EvaluationSettingsToJson(settings_)}, {"ensemble", size_}, {"genomes", genomes}};
  WriteFileAtomically(path_, out.dump(1) + "\n");
}

json RescoreJson(const FitnessEnsemble& ensemble, double recorded) {
  const std::size_t n = ensemble.fitness.size();
  const json reproduced = n % 2 == 1 ? json(ensemble.fitness[(n - 1) / 2] == recorded) : json(nullptr);
  return {{"fitness", ensemble.fitness}, {"median", ensemble.Median()}, {"min", ensemble.Min()},
          {"max", ensemble.Max()},       {"bipeds", ensemble.bipeds},   {"tripods", ensemble.tripods},
          {"falls", ensemble.falls},     {"recorded_reproduced", reproduced}};
}

}  // namespace walkers
