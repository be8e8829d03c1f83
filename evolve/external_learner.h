// The external learner: a learner whose proposals come from a program outside
// this one (an optimiser in Python, through the module's walkers.Run:
// docs/python.md). The run is the same as a built-in learner's: the
// scaffold's ceiling, the GA's admission rules, evaluation, the archive, the
// files and checkpoints are EvolutionRun's. Only the three questions a run
// asks its learner go out: the generation's proposals, the evaluated children
// (told) and the learner's state for the checkpoint, which the outside program
// gives as any JSON value and gets back when the run resumes.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/learner.h"

namespace walkers {

struct GeneticAlgorithmConfig;

// The outside program, as the external learner sees it. Its calls come from
// the run's thread, one at a time, in the order Propose, Tell, State for each
// generation; any of them may throw to end the run.
class ProposalSource {
 public:
  virtual ~ProposalSource() = default;
  // generation in.generation's children's genomes, `children` of them
  virtual std::vector<Genome> Propose(const BreedingInputs& in, int children) = 0;
  // the children as the run evaluated them (after the GA's rules), in order
  virtual void Tell(const BreedingInputs& in, const std::vector<Individual>& evaluated) = 0;
  // the program's state after it was told, for the checkpoint
  virtual nlohmann::json State() = 0;
};

class ExternalLearner : public Learner {
 public:
  // `source` may be null (a learner made to read a checkpoint): it then
  // proposes nothing, and a run of it is an error naming walkers.Run.
  ExternalLearner(const LearnerSpec& spec, int population, ProposalSource* source)
      : Learner(spec), population_(population), source_(source) {}

  // the source's genomes, checked to be one per child; their parents name the learner
  std::vector<Individual> Propose(const BreedingInputs& in, const Archive& archive) override;
  void Tell(const BreedingInputs& in, const std::vector<Individual>& evaluated) override;

  bool KeepsState() const override { return true; }
  // {"state": the source's state}
  nlohmann::json State() const override;
  // keeps the state for the source to take (restored_state); throws
  // InputError naming `source` when `state` is not State()'s form
  void Restore(const nlohmann::json& state, int completed_generations, const std::string& source) override;
  // the state a resumed run was checkpointed with; null for a fresh run
  const nlohmann::json& restored_state() const { return restored_; }

 private:
  ProposalSource& Source(const BreedingInputs& in) const;

  int population_;
  ProposalSource* source_;
  nlohmann::json restored_;
};

// The learner list's maker: an external learner without a source.
std::unique_ptr<Learner> MakeExternalLearner(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga,
                                             std::uint64_t seed);

}  // namespace walkers
