// pagmo2's CMA-ES, self-adaptive differential evolution (sade: jDE) and
// generational particle swarm (pso_gen) as learners (evolve/learner.h). The
// library does the learning; here they are run one generation at a time: the
// decision vector is the genome's 18 genes within this generation's bounds
// (ChildGeneBounds: the scaffold's on halfBodyX, Table 1's on the others),
// the objective is -fitness (pagmo minimises), population 16 by default so
// that the budget per generation is the GA's. Generation 0 is the GA's (the
// default genome and its mutants), so every learner starts from the same
// children; each later generation asks pagmo's algorithm for the children's
// genomes, and the run evaluates them on its own threads.
#pragma once

#include <cstdint>
#include <memory>

#include "evolve/learner.h"

namespace walkers {

std::unique_ptr<Learner> MakeCmaes(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga, std::uint64_t seed);
std::unique_ptr<Learner> MakeSade(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga, std::uint64_t seed);
std::unique_ptr<Learner> MakeParticleSwarm(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga,
                                           std::uint64_t seed);

// What the list of learners says of them.
extern const char* const kCmaesAbout;
extern const char* const kSadeAbout;
extern const char* const kParticleSwarmAbout;
constexpr int kCmaesMinPopulation = 5;          // pagmo's cmaes needs 5
constexpr int kSadeMinPopulation = 7;           // pagmo's sade draws 7 distinct members
constexpr int kParticleSwarmMinPopulation = 2;  // as the GA

}  // namespace walkers
