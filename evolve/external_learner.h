// The external learner: a learner whose proposals come from a program outside
// this one (an optimiser in Python, through the module's walkers.Run:
// docs/python.md). The run is the same as a built-in learner's: the
// scaffold's ceiling, the GA's admission rules, evaluation, the archive, the
// files and checkpoints are EvolutionRun's. The outside program drives the
// run's generations itself (EvolutionRun::BeginGeneration, EvaluateChildren,
// FinishGeneration): it proposes the children (Children), is given them
// evaluated, and hands its state for the checkpoint (StateOf), any JSON value,
// which it gets back when the run resumes (restored_state).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/learner.h"

namespace walkers {

struct GeneticAlgorithmConfig;

class ExternalLearner : public Learner {
 public:
  ExternalLearner(const LearnerSpec& spec, int population) : Learner(spec), population_(population) {}

  // Generation in.generation's children from the outside program's genomes,
  // one per child; their lineage names the learner. Throws InputError when
  // there are not as many genomes as children.
  std::vector<Individual> Children(const BreedingInputs& in, const std::vector<Genome>& genomes) const;

  // Throws InputError: the outside program proposes, through the Python
  // module's walkers.Run, never the run's own loop (EvolutionRun::Run).
  std::vector<Individual> Propose(const BreedingInputs& in, const Archive& archive) override;
  void Tell(const BreedingInputs&, const std::vector<Individual>&) override {}

  bool KeepsState() const override { return true; }
  // checkpoint.json's "learner" for the outside program's state: {"state": it},
  // an object even when the state is null
  static nlohmann::json StateOf(const nlohmann::json& program_state);
  // StateOf the state the run was resumed with (null for a fresh run)
  nlohmann::json State() const override { return StateOf(restored_); }
  // keeps the state for the outside program to take (restored_state); throws
  // InputError naming `source` when `state` is not StateOf's form
  void Restore(const nlohmann::json& state, int completed_generations, const std::string& source) override;
  // the state a resumed run was checkpointed with; null for a fresh run
  const nlohmann::json& restored_state() const { return restored_; }

 private:
  int population_;
  nlohmann::json restored_;
};

// The learner list's maker.
std::unique_ptr<Learner> MakeExternalLearner(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga,
                                             std::uint64_t seed);

}  // namespace walkers
