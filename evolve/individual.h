// The evaluated individuals of a run and the run's all-time archive of the
// fittest (MODEL.md §5's F): what every learner's children become once
// evaluated, and what the performance scaffold and the results read.
#pragma once

#include <string>
#include <vector>

#include "control/evaluation.h"
#include "control/genome.h"
#include "control/preset.h"

namespace walkers {

struct Individual {
  int generation = 0;
  int child = 0;
  // "" for the default genome, "g/c" for a mutant, "g/c+g/c" for a crossover
  // child; another learner's children name the learner ("cmaes")
  std::string parents;
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

}  // namespace walkers
