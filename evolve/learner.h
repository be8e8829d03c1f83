// The learner seam: what learns under a scaffold. Each generation a learner
// proposes its children's genomes within the scaffold's bounds, is told their
// evaluations, and keeps its whole state (random streams included) in the
// run's checkpoint, so that a resumed run is the uninterrupted one. The run
// (evolve/run.h) owns the rest: the scaffold, the archive, evaluation, files
// and progress. Learners() is the one list of learners: the paper's genetic
// algorithm (the default); pagmo2's CMA-ES, self-adaptive differential
// evolution and particle swarm (evolve/pagmo_learners.h); and the external
// learner, an optimiser outside walkers proposing through the Python module
// (evolve/external_learner.h).
#pragma once

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "evolve/individual.h"
#include "evolve/random.h"
#include "evolve/scaffold.h"
#include "evolve/variation.h"

namespace walkers {

struct GeneticAlgorithmConfig;

// Everything that decides a generation's children.
struct BreedingInputs {
  std::uint64_t seed = 1;
  int generation = 0;
  double body_ceiling = kBodyCeiling;  // the scaffold's ceiling on halfBodyX this generation
  MutationRules rules;
};

// The interval a child's gene must lie in [its units], where the scaffold
// puts halfBodyX's ceiling at `body_ceiling`: the gene's bounds (Table 1),
// with the scaffold's ceiling on halfBodyX. When the ceiling falls below
// halfBodyX's floor (the authors' case-3 formula allows it), the authors'
// clamp, ceiling first, leaves the gene at the ceiling or at the floor, and
// the interval spans both.
struct GeneBounds {
  double lo = 0, hi = 0;
};
GeneBounds ChildGeneBounds(int gene, double body_ceiling);

class Learner;

// Everything the program knows of one learner.
struct LearnerSpec {
  const char* name;    // on the command line and in files: "cmaes"
  const char* label;   // for people: "CMA-ES"
  const char* colour;  // its colour in the figures (a matplotlib colour name)
  const char* about;   // one line: where it comes from, its settings
  int min_population;  // the fewest children a generation may have for it
  // a learner of this kind for a run of `ga`'s sizes and `seed`
  std::unique_ptr<Learner> (*make)(const LearnerSpec& self, const GeneticAlgorithmConfig& ga, std::uint64_t seed);
  // proposes from a program outside walkers (ExternalLearner): its runs are
  // driven through the Python module, never by `walkers evolve` or `reproduce`
  bool external = false;
};

class Learner {
 public:
  explicit Learner(const LearnerSpec& spec) : spec_(&spec) {}
  virtual ~Learner() = default;
  const LearnerSpec& spec() const { return *spec_; }

  // The children of generation in.generation, in order (generation and child
  // set), not yet evaluated: each one's genome and where it came from
  // (Individual::lineage). `archive` is the run's all-time fittest so far
  // (empty before generation 0). The run then applies the GA's rules to them
  // (AdmitChildren).
  virtual std::vector<Individual> Propose(const BreedingInputs& in, const Archive& archive) = 0;

  // `child` (its generation, number and lineage set) drawn again, because
  // `proposal`, its genome, was seen before. By default, as the GA draws a
  // child again: a mutant of the proposal, from `rng`, the child's own stream
  // of redraws (continued from one redraw to the next); its lineage adds
  // kRedrawn.
  virtual void Redraw(const BreedingInputs& in, const Genome& proposal, Random* rng, Individual* child);

  // The generation's children as the run evaluated them (after AdmitChildren),
  // in the order Propose gave them.
  virtual void Tell(const BreedingInputs& in, const std::vector<Individual>& evaluated) = 0;

  // Whether the learner has a state of its own beyond the run's archive (the
  // GA has none: its children come from the archive and the seed alone).
  virtual bool KeepsState() const { return false; }
  // That state after the generations it was told, for checkpoint.json.
  virtual nlohmann::json State() const;
  // Restores a State() of a learner of this kind and settings after
  // `completed_generations` generations, checked: throws InputError naming
  // `source` and the field ("learner.population[3].x[0]").
  virtual void Restore(const nlohmann::json& state, int completed_generations, const std::string& source);

 private:
  const LearnerSpec* spec_;
};

// The GA's rules (docs/model.md, "Genetic algorithm") applied to a learner's
// proposals, child by child in order: a gene outside its bounds
// (ChildGeneBounds) is clamped into them, as mutation clamps (but for the
// initial individual, the default genome in generation 0, evaluated as it
// is); a genome whose 3-significant-figure key was seen is drawn again
// (Learner::Redraw) until it is new (a run that finds none in 100000 draws
// throws); each accepted key is added to `seen`. A gene that is
// not a finite number is the learner's bug: WALKERS_CHECK's std::logic_error
// naming the learner, the child and the gene.
void AdmitChildren(Learner& learner, const BreedingInputs& in, std::vector<Individual>* children,
                   std::set<GenomeKey>* seen);

// The learners; the first, the paper's GA, is the default.
const std::vector<LearnerSpec>& Learners();
const LearnerSpec& DefaultLearner();
// every learner's name, as run files may name it
std::vector<std::string> LearnerNames();
// the learners walkers runs itself (`evolve --learner`, `reproduce --learners`)
std::vector<std::string> BuiltInLearnerNames();
// Throws InputError (files/errors.h) naming the allowed values.
const LearnerSpec& LearnerByName(const std::string& name);
// LearnerByName(name)'s learner for a run of `ga`'s sizes and `seed`.
std::unique_ptr<Learner> MakeLearner(const std::string& name, const GeneticAlgorithmConfig& ga, std::uint64_t seed);

}  // namespace walkers
