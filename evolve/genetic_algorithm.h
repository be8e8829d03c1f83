// The genetic algorithm of paper Algorithm 1 with the authors' settings
// (MODEL.md §5): an all-time archive of the fittest, mutation and crossover
// children drawn from it, duplicates redrawn.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "control/evaluation.h"
#include "control/genome.h"
#include "control/preset.h"
#include "evolve/scaffold.h"
#include "evolve/variation.h"

namespace walkers {

// Generation 1 breeds from an archive of at least two: generation 0 must
// have as many children.
constexpr int kMinPopulation = 2;
constexpr int kMaxPopulation = 100000;
constexpr int kMinArchive = 2;
constexpr int kMaxArchive = 100000;

struct GeneticAlgorithmConfig {
  int population = 16;         // children per generation; generation 0 = default + population-1 mutants
  int archive_size = 16;       // the all-time fittest kept
  int mutation_children = 10;  // per generation; the rest are crossover children
  double mutation_probability = 0.9;  // (0, 1]: at 0 every mutant would repeat its parent

  // Throws std::invalid_argument naming the field and its allowed range.
  void Validate() const;
  int crossover_children() const { return population - mutation_children; }
};

struct Individual {
  int generation = 0;
  int child = 0;
  std::string parents;  // "" for the default genome, "g/c" for a mutant, "g/c+g/c" for a crossover child
  Genome genome;
  EvaluationResult result;

  std::string id() const { return std::to_string(generation) + "/" + std::to_string(child); }
  double fitness() const { return result.fitness; }
};

// The archive's order: the fitter first; at equal fitness the older.
bool Fitter(const Individual& a, const Individual& b);

// The all-time fittest: best first; equal fitness keeps the older individual.
class Archive {
 public:
  explicit Archive(int capacity) : capacity_(capacity) {}
  void Merge(const std::vector<Individual>& children);
  const std::vector<Individual>& members() const { return members_; }
  bool empty() const { return members_.empty(); }
  const Individual& best() const { return members_.front(); }
  double AverageOfBest(int n) const;  // mean fitness of the best n (or of all, if fewer)
  double Mean() const;
  void Restore(std::vector<Individual> members) { members_ = std::move(members); }

 private:
  int capacity_;
  std::vector<Individual> members_;
};

// Everything that decides a generation's children.
struct BreedingInputs {
  std::uint64_t seed = 1;
  int generation = 0;
  double body_ceiling = kBodyCeiling;
  MutationRules rules;
};

// The children of one generation, in order, not yet evaluated. Generation 0 is
// the default genome and its mutants; later ones come from the archive.
// Every accepted child's key is added to `seen`; a child whose key was seen is
// drawn again (a run that cannot find a new genome in 100000 draws throws).
std::vector<Individual> Breed(const GeneticAlgorithmConfig& config, const BreedingInputs& in, const Archive& archive,
                              std::set<GenomeKey>* seen);

// Evaluates every individual on `threads` worker threads. Results depend only
// on the genomes, never on the threads.
void EvaluateAll(std::vector<Individual>* individuals, const Preset& preset, const EvaluationSettings& settings,
                 int threads);

}  // namespace walkers
