#include "evolve/external_learner.h"

#include <stdexcept>
#include <string>

#include "files/input_file.h"
#include "evolve/genetic_algorithm.h"

namespace walkers {

ProposalSource& ExternalLearner::Source(const BreedingInputs& in) const {
  if (source_ == nullptr) {
    throw std::runtime_error("generation " + std::to_string(in.generation) + ": the learner " + spec().name +
                             " proposes from a program outside walkers; drive its run with the Python module's "
                             "walkers.Run (docs/python.md)");
  }
  return *source_;
}

std::vector<Individual> ExternalLearner::Propose(const BreedingInputs& in, const Archive&) {
  const std::vector<Genome> genomes = Source(in).Propose(in, population_);
  if (static_cast<int>(genomes.size()) != population_) {
    throw std::runtime_error("generation " + std::to_string(in.generation) + ": the learner " + spec().name +
                             " proposed " + std::to_string(genomes.size()) + " genomes for " +
                             std::to_string(population_) + " children");
  }
  std::vector<Individual> children(genomes.size());
  for (std::size_t c = 0; c < children.size(); ++c) {
    children[c].generation = in.generation;
    children[c].child = static_cast<int>(c);
    children[c].parents = spec().name;
    children[c].genome = genomes[c];
  }
  return children;
}

void ExternalLearner::Tell(const BreedingInputs& in, const std::vector<Individual>& evaluated) {
  Source(in).Tell(in, evaluated);
}

// checkpoint.json's "learner": {"state": the program's state}, an object even
// when the program's state is null
nlohmann::json ExternalLearner::State() const {
  return {{"state", source_ == nullptr ? restored_ : source_->State()}};
}

void ExternalLearner::Restore(const nlohmann::json& state, int, const std::string& source) {
  const JsonFields f(state, source, "learner.");
  f.RequireOnly({"state"});
  restored_ = f.Get("state");
}

std::unique_ptr<Learner> MakeExternalLearner(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga,
                                             std::uint64_t) {
  return std::make_unique<ExternalLearner>(spec, ga.population, nullptr);
}

}  // namespace walkers
