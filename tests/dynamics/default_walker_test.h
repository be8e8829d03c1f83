// Base fixture of the dynamics tests: the model of the default genome and a
// random generator, seeded by each test file so that its draws stay its own.
#pragma once

#include <random>

#include <gtest/gtest.h>

#include "control/genome.h"
#include "dynamics/coords.h"
#include "dynamics/model.h"
#include "tests/finite_difference.h"

namespace walkers::testing {

class DefaultWalkerTest : public ::testing::Test {
 protected:
  explicit DefaultWalkerTest(std::mt19937::result_type seed) : rng_(seed) {}

  // a random configuration: every coordinate uniform in [-1.5, 1.5]
  Vec9 RandomQ() { return RandomVector<kNumCoords>(rng_, -1.5, 1.5); }

  Model model_ = BuildModel(BodyOf(DefaultGenome()));
  std::mt19937 rng_;
};

}  // namespace walkers::testing
