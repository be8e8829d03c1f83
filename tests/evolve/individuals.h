// Hand-made individuals for the archive and breeding tests.
#pragma once

#include <map>
#include <memory>

#include "control/genome.h"
#include "evolve/evaluator.h"
#include "evolve/individual.h"

namespace walkers::testing {

// An evaluated individual of the given generation and child with the given
// fitness; its genome is the default one with kx set apart, so that no two
// (generation, child) pairs share a genome.
inline Individual WithFitness(int generation, int child, double fitness) {
  Individual ind;
  ind.generation = generation;
  ind.child = child;
  ind.genome = DefaultGenome();
  ind.genome[kKx] = 100.0 * generation + child;
  ind.result.fitness = fitness;
  return ind;
}

// An evaluator of `threads` threads of this process, shared by the tests.
inline Evaluator& Threads(int threads) {
  static std::map<int, std::unique_ptr<Evaluator>> evaluators;
  std::unique_ptr<Evaluator>& e = evaluators[threads];
  if (!e) e = MakeThreadEvaluator(threads);
  return *e;
}

}  // namespace walkers::testing
