#include "evolve/learner.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "evolve/external_learner.h"
#include "evolve/genetic_algorithm.h"
#include "evolve/pagmo_learners.h"
#include "files/errors.h"
#include "files/input_file.h"

namespace walkers {
namespace {

constexpr int kMaxDraws = 100000;

// Clamps every gene of `genome` into its bounds; true if one was outside.
bool ClampIntoBounds(double body_ceiling, Genome* genome) {
  bool clamped = false;
  for (int k = 0; k < kNumGenes; ++k) {
    const GeneBounds b = ChildGeneBounds(k, body_ceiling);
    const double x = std::clamp(genome->genes[k], b.lo, b.hi);
    clamped = clamped || x != genome->genes[k];
    genome->genes[k] = x;
  }
  return clamped;
}

void RequireFinite(const std::string& learner, const Individual& child) {
  for (int k = 0; k < kNumGenes; ++k) {
    WALKERS_CHECK(std::isfinite(child.genome.genes[k]),
                  "the learner " + learner + " proposed " + std::to_string(child.genome.genes[k]) + " for gene '" +
                      GeneTable()[k].name + "' of child " + child.id() + ": a gene must be a finite number");
  }
}

}  // namespace

GeneBounds ChildGeneBounds(int gene, double body_ceiling) {
  const GeneSpec& spec = GeneTable()[gene];
  if (gene != kHalfBodyX) return {spec.floor, spec.ceiling};
  return {std::min(spec.floor, body_ceiling), std::max(spec.floor, body_ceiling)};
}

void Learner::Redraw(const BreedingInputs& in, const Genome& proposal, Random* rng, Individual* child) {
  child->genome = Mutate(proposal, in.body_ceiling, in.rules, rng);
  child->lineage.admissions.push_back(Lineage::Admission::kRedrawn);
}

nlohmann::json Learner::State() const { return nullptr; }

void Learner::Restore(const nlohmann::json& state, int, const std::string& source) {
  if (!state.is_null()) throw InputError(source + ": field 'learner' is given, but this run's learner keeps no state");
}

void AdmitChildren(Learner& learner, const BreedingInputs& in, std::vector<Individual>* children,
                   std::set<GenomeKey>* seen) {
  const std::string learner_name = learner.spec().name;
  const Genome initial = DefaultGenome();
  for (Individual& child : *children) {
    RequireFinite(learner_name, child);
    // the initial individual is evaluated as it is, whatever the scaffold's
    // ceiling (the authors' generation 0 holds the default genome itself)
    const bool is_initial = in.generation == 0 && child.genome.genes == initial.genes;
    if (!is_initial && ClampIntoBounds(in.body_ceiling, &child.genome)) {
      child.lineage.admissions.push_back(Lineage::Admission::kClamped);
    }
    if (seen->insert(KeyOf(child.genome)).second) continue;
    // a genome seen before: drawn again, from the child's own stream of redraws
    const Individual proposal = child;
    Random rng(in.seed, in.generation, Random::kRedraws + static_cast<std::uint64_t>(child.child));
    bool found = false;
    for (int draw = 0; draw < kMaxDraws && !found; ++draw) {
      child = proposal;
      learner.Redraw(in, proposal.genome, &rng, &child);
      RequireFinite(learner_name, child);
      if (ClampIntoBounds(in.body_ceiling, &child.genome)) {
        child.lineage.admissions.push_back(Lineage::Admission::kClamped);
      }
      found = seen->insert(KeyOf(child.genome)).second;
    }
    if (!found) {
      throw std::runtime_error("no new genome in " + std::to_string(kMaxDraws) +
                               " draws: every mutant was a duplicate");
    }
  }
}

const std::vector<LearnerSpec>& Learners() {
  static const std::vector<LearnerSpec> learners = {
      {"ga", "genetic algorithm", "tab:blue",
       "the paper's genetic algorithm (Algorithm 1; docs/model.md, \"Genetic algorithm\"), the default", kMinPopulation,
       MakeGeneticAlgorithm},
      {"cmaes", "CMA-ES", "tab:red", kCmaesAbout, kCmaesMinPopulation, MakeCmaes},
      {"sade", "self-adaptive DE", "tab:olive", kSadeAbout, kSadeMinPopulation, MakeSade},
      {"pso", "particle swarm", "tab:brown", kParticleSwarmAbout, kParticleSwarmMinPopulation, MakeParticleSwarm},
      {"external", "external (Python)", "tab:cyan",
       "an optimiser outside walkers, proposing through the Python module's walkers.Run (docs/python.md)",
       kMinPopulation, MakeExternalLearner, true},
  };
  return learners;
}

const LearnerSpec& DefaultLearner() { return Learners().front(); }

std::vector<std::string> LearnerNames() {
  std::vector<std::string> names;
  for (const LearnerSpec& spec : Learners()) names.push_back(spec.name);
  return names;
}

std::vector<std::string> BuiltInLearnerNames() {
  std::vector<std::string> names;
  for (const LearnerSpec& spec : Learners()) {
    if (!spec.external) names.push_back(spec.name);
  }
  return names;
}

const LearnerSpec& LearnerByName(const std::string& name) {
  for (const LearnerSpec& spec : Learners()) {
    if (name == spec.name) return spec;
  }
  FailUnknownName("learner", name, LearnerNames());
}

std::unique_ptr<Learner> MakeLearner(const std::string& name, const GeneticAlgorithmConfig& ga, std::uint64_t seed) {
  const LearnerSpec& spec = LearnerByName(name);
  return spec.make(spec, ga, seed);
}

}  // namespace walkers
