// The genetic algorithm of paper Algorithm 1 with the authors' settings
// (docs/model.md, "Genetic algorithm"), the default learner: children drawn
// from the run's all-time archive by mutation and crossover, duplicates drawn
// again.
#pragma once

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "evolve/individual.h"
#include "evolve/learner.h"
#include "evolve/random.h"
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

  // Throws InputError naming `source` (the file, when the settings come from
  // one), the field and its allowed range.
  void Validate(const std::string& source = "") const;
  int crossover_children() const { return population - mutation_children; }
};

// Paper Algorithm 1. Generation 0 is the default genome and its mutants;
// later generations make mutation children (parents drawn from a shuffled
// archive without replacement) and crossover children (the mean of two
// parents drawn without replacement, then mutated). Each child draws from its
// own stream (seed, generation, child); a child drawn again continues it.
// Its state is the run's archive: it keeps none of its own.
class GeneticAlgorithm : public Learner {
 public:
  GeneticAlgorithm(const LearnerSpec& spec, const GeneticAlgorithmConfig& config) : Learner(spec), config_(config) {}

  // Generation 0: the default genome and population-1 mutants of it; later
  // generations need an archive of two or more (WALKERS_CHECK).
  std::vector<Individual> Propose(const BreedingInputs& in, const Archive& archive) override;
  // The child's next draw from its parent (or its parents' mean) and stream.
  void Redraw(const BreedingInputs& in, const Genome& proposal, Random* rng, Individual* child) override;
  void Tell(const BreedingInputs&, const std::vector<Individual>&) override {}

 private:
  // what a child of this generation is drawn from
  struct Draw {
    Genome base;  // its parent, or its parents' mean
    Random rng;   // its stream
  };
  GeneticAlgorithmConfig config_;
  std::vector<Draw> draws_;
};

std::unique_ptr<Learner> MakeGeneticAlgorithm(const LearnerSpec& spec, const GeneticAlgorithmConfig& config,
                                              std::uint64_t seed);

// The children of one generation, in order, not yet evaluated: the GA's
// proposals with the GA's rules applied (AdmitChildren). Every accepted
// child's key is added to `seen`; a child whose key was seen is drawn again.
std::vector<Individual> Breed(const GeneticAlgorithmConfig& config, const BreedingInputs& in, const Archive& archive,
                              std::set<GenomeKey>* seen);

}  // namespace walkers
