// The evaluated individuals of a run, where each came from, and the run's
// all-time archive of the fittest (F in docs/model.md, "Genetic algorithm"):
// what every learner's children become once evaluated, and what the
// performance scaffold and the results read.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "control/evaluation.h"
#include "control/genome.h"
#include "control/preset.h"

namespace walkers {

// Where an individual came from: its parents in the run, or the learner that
// proposed it, and what the GA's rules did to it on admission (AdmitChildren).
// Files spell it as text (evaluations.csv's `parents` column, the archive's
// "parents"): "" for the initial individual, "g/c" for a mutant of individual
// g/c, "g/c+g/c" for a crossover child, the learner's name for another
// learner's child ("cmaes"); then " clamped" for each time it was clamped
// into its bounds and " redrawn" for each time it was drawn again, in order.
struct Lineage {
  struct Parent {
    int generation = 0;
    int child = 0;
    bool operator==(const Parent& o) const { return generation == o.generation && child == o.child; }
  };
  enum class Admission { kClamped, kRedrawn };

  std::vector<Parent> parents;        // none, one (a mutant) or two (a crossover child)
  std::string learner;                // the learner that proposed it, when it names no parents
  std::vector<Admission> admissions;  // what the GA's rules did, in order

  static Lineage Of(std::vector<Parent> parents) { return {std::move(parents), "", {}}; }
  static Lineage ProposedBy(std::string learner) { return {{}, std::move(learner), {}}; }

  // The text files hold.
  std::string Text() const;
  // A lineage's text back (Text() of it is `text`); nothing for text that is
  // not one.
  static std::optional<Lineage> FromText(const std::string& text);

  bool operator==(const Lineage& o) const {
    return parents == o.parents && learner == o.learner && admissions == o.admissions;
  }
};

struct Individual {
  int generation = 0;
  int child = 0;
  Lineage lineage;
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
