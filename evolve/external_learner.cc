#include "evolve/external_learner.h"

#include <string>

#include "evolve/genetic_algorithm.h"
#include "files/input_file.h"

namespace walkers {

std::vector<Individual> ExternalLearner::Children(const BreedingInputs& in, const std::vector<Genome>& genomes) const {
  if (static_cast<int>(genomes.size()) != population_) {
    throw InputError("generation " + std::to_string(in.generation) + ": the learner " + spec().name + " proposed " +
                     std::to_string(genomes.size()) + " genomes for " + std::to_string(population_) + " children");
  }
  std::vector<Individual> children(genomes.size());
  for (std::size_t c = 0; c < children.size(); ++c) {
    children[c].generation = in.generation;
    children[c].child = static_cast<int>(c);
    children[c].lineage = Lineage::ProposedBy(spec().name);
    children[c].genome = genomes[c];
  }
  return children;
}

std::vector<Individual> ExternalLearner::Propose(const BreedingInputs& in, const Archive&) {
  throw InputError("generation " + std::to_string(in.generation) + ": the learner " + spec().name +
                   " proposes from a program outside walkers; drive its run with the Python module's walkers.Run "
                   "(docs/python.md)");
}

nlohmann::json ExternalLearner::StateOf(const nlohmann::json& program_state) { return {{"state", program_state}}; }

void ExternalLearner::Restore(const nlohmann::json& state, int, const std::string& source) {
  const JsonFields f(state, source, "learner.");
  f.RequireOnly({"state"});
  restored_ = f.Get("state");
}

std::unique_ptr<Learner> MakeExternalLearner(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga,
                                             std::uint64_t) {
  return std::make_unique<ExternalLearner>(spec, ga.population);
}

}  // namespace walkers
