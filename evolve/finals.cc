#include "evolve/finals.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "control/input_file.h"
#include "evolve/files.h"

namespace walkers {
namespace {

using nlohmann::json;

// the settings as config.json writes them
json SettingsJson(const EvaluationSettings& settings) {
  RunConfig config;
  config.evaluation = settings;
  return RunConfigToJson(config).at("evaluation");
}

}  // namespace

RunFinals LoadRunFinals(const std::string& dir, const RunConfig& config) {
  const RunFiles files(dir);
  RunFinals finals{LoadArchive(files.archive, config).front(), std::nullopt, std::nullopt};

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
      throw std::runtime_error(files.evaluations + ": generation " + std::to_string(g) + " has " +
                               std::to_string(per_generation[g]) + " evaluations, not the population's " +
                               std::to_string(config.ga.population));
    }
  }
  return finals;
}

RescoreCache::RescoreCache(std::string path, const Preset& preset, const EvaluationSettings& settings, int size)
    : path_(std::move(path)), preset_(preset), settings_(settings), size_(size) {
  if (!std::filesystem::exists(path_)) return;
  try {
    const json j = LoadJsonFile(path_);
    const JsonFields f(j, path_);
    f.RequireOnly({"preset", "evaluation", "ensemble", "genomes"});
    // another preset, other settings or another size: none of its ensembles is of use
    if (f.String("preset") != preset_.name || f.Get("evaluation") != SettingsJson(settings_) ||
        f.Integer("ensemble", 1, kMaxEnsemble) != size_) {
      return;
    }
    const json& genomes = f.Array("genomes");
    for (std::size_t i = 0; i < genomes.size(); ++i) {
      const JsonFields e(genomes[i], path_, "genomes[" + std::to_string(i) + "].");
      e.RequireOnly({"genome", "fitness", "bipeds", "tripods", "falls"});
      const Genome genome = GenomeFromJson(e.Get("genome"), path_ + ": " + e.Name("genome"));
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
  } catch (const InputError& e) {
    throw std::runtime_error(std::string(e.what()) + " (a cache of re-scores: remove it to evaluate them again)");
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
      {"preset", preset_.name}, {"evaluation", SettingsJson(settings_)}, {"ensemble", size_}, {"genomes", genomes}};
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
