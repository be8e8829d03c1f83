// Every learner of the list, driven without the simulator: a synthetic
// fitness stands in for the walker, a falling ceiling for the scaffold.
#include "evolve/pagmo_learners.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evolve/genetic_algorithm.h"
#include "files/input_file.h"

namespace walkers {
namespace {

// Falls with the distance, in units of each gene's width, from a genome
// inside the bounds; never a walker's fitness, but one a learner can climb.
double SyntheticFitness(const Genome& g) {
  double d2 = 0;
  for (int k = 0; k < kNumGenes; ++k) {
    const GeneSpec& s = GeneTable()[k];
    const double target = s.floor + 0.3 * (s.ceiling - s.floor);
    const double u = (g.genes[k] - target) / (s.ceiling - s.floor);
    d2 += u * u;
  }
  return 10.0 - 10.0 * std::sqrt(d2);
}

// A scaffold's ceiling: the gene's own for 5 generations, then falling below
// halfBodyX's floor by generation 20.
double CeilingAt(int generation) {
  if (generation < 5) return kBodyCeiling;
  return std::max(0.02, kBodyCeiling - (kBodyCeiling - 0.02) * (generation - 4) / 15.0);
}

// One run of a learner without the simulator.
struct Driven {
  explicit Driven(const std::string& name, std::uint64_t run_seed = 11)
      : seed(run_seed), learner(MakeLearner(name, Config(), run_seed)), archive(Config().archive_size) {}

  static GeneticAlgorithmConfig Config() {
    GeneticAlgorithmConfig ga;  // the paper's sizes: 16 children, 10 of them mutants
    return ga;
  }

  // generations [completed, to); records each generation's proposals (before
  // the GA's rules) and children (after)
  void RunTo(int to) {
    const MutationRules rules{0.9, BodyGeneMutation::kLikeEveryGene, AuthorsBodyRedraw::kAfterEveryMutatedGene};
    for (int g = completed; g < to; ++g) {
      const BreedingInputs in{seed, g, CeilingAt(g), rules};
      std::vector<Individual> children = learner->Propose(in, archive);
      proposals.push_back(children);
      AdmitChildren(*learner, in, &children, &seen);
      for (Individual& c : children) {
        c.result.fitness = SyntheticFitness(c.genome);
        best = std::max(best, c.fitness());
      }
      evaluated.push_back(children);
      // a blind learner (and archive) is told the same fitness for every child
      if (blind) {
        for (Individual& c : children) c.result.fitness = 0;
      }
      learner->Tell(in, children);
      archive.Merge(children);
      completed = g + 1;
    }
  }

  std::uint64_t seed;
  std::unique_ptr<Learner> learner;
  Archive archive;
  std::set<GenomeKey> seen;
  int completed = 0;
  bool blind = false;
  double best = -1e300;  // the best synthetic fitness evaluated
  std::vector<std::vector<Individual>> proposals, evaluated;
};

class EveryLearnerTest : public ::testing::TestWithParam<std::string> {};

INSTANTIATE_TEST_SUITE_P(Learners, EveryLearnerTest, ::testing::ValuesIn(BuiltInLearnerNames()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

TEST_P(EveryLearnerTest, ProposalsRespectTheScaffoldsCeilingAndTheGenesBounds) {
  Driven run(GetParam());
  run.RunTo(24);
  int at_or_below_floor = 0;
  for (int g = 0; g < run.completed; ++g) {
    for (const Individual& p : run.proposals[g]) {
      ASSERT_EQ(p.generation, g);
      if (g == 0 && p.genome.genes == DefaultGenome().genes) continue;  // the initial individual
      for (int k = 0; k < kNumGenes; ++k) {
        const GeneBounds b = ChildGeneBounds(k, CeilingAt(g));
        EXPECT_GE(p.genome.genes[k], b.lo) << GeneTable()[k].name << " of " << p.id();
        EXPECT_LE(p.genome.genes[k], b.hi) << GeneTable()[k].name << " of " << p.id();
      }
      at_or_below_floor += p.genome[kHalfBodyX] <= kBodyFloor ? 1 : 0;
    }
  }
  // the ceiling reached halfBodyX's floor and went below it, and the
  // proposals followed it (the default genome's halfBodyX is 0.88)
  EXPECT_GT(at_or_below_floor, 0);
}

TEST_P(EveryLearnerTest, LearnsFromWhatItIsTold) {
  Driven told(GetParam()), blind(GetParam());
  blind.blind = true;
  told.RunTo(40);
  blind.RunTo(40);
  // the synthetic optimum is 10; generation 0 (the default genome and its
  // mutants) is far from it, and a learner that is told nothing stays farther
  double first = -1e300;
  for (const Individual& c : told.evaluated[0]) first = std::max(first, c.fitness());
  EXPECT_GT(told.best, first + 1.0);
  EXPECT_GT(told.best, blind.best + 0.5) << "blind: " << blind.best;
}

TEST_P(EveryLearnerTest, ARestoredStateProposesBitForBitWhatTheUninterruptedLearnerDoes) {
  Driven whole(GetParam());
  whole.RunTo(14);

  Driven first(GetParam());
  first.RunTo(7);
  // the state through the checkpoint's text, into a new learner of the same kind and seed
  const std::string saved = first.learner->State().dump();
  Driven resumed(GetParam());
  resumed.learner->Restore(ParseJson(saved, "checkpoint.json"), 7, "checkpoint.json");
  resumed.archive = first.archive;
  resumed.seen = first.seen;
  resumed.completed = 7;
  resumed.RunTo(14);
  for (int g = 7; g < 14; ++g) {
    for (int c = 0; c < 16; ++c) {
      EXPECT_EQ(resumed.evaluated[g - 7][c].genome.genes, whole.evaluated[g][c].genome.genes) << g << "/" << c;
      EXPECT_EQ(resumed.evaluated[g - 7][c].lineage, whole.evaluated[g][c].lineage) << g << "/" << c;
    }
  }
  if (!whole.learner->KeepsState()) return;
  // the state is what made it so: a learner that lost it proposes other children
  Driven forgetful(GetParam());
  forgetful.RunTo(1);  // generation 0 again (the GA's), then the archive as it was
  forgetful.archive = first.archive;
  forgetful.seen = first.seen;
  forgetful.completed = 7;
  forgetful.RunTo(8);
  EXPECT_NE(forgetful.evaluated[1][0].genome.genes, whole.evaluated[7][0].genome.genes);
}

TEST_P(EveryLearnerTest, TheSameSeedProposesTheSameAndAnotherSeedOtherwise) {
  Driven a(GetParam(), 5), b(GetParam(), 5), other(GetParam(), 6);
  a.RunTo(6);
  b.RunTo(6);
  other.RunTo(6);
  for (int g = 0; g < 6; ++g) {
    for (int c = 0; c < 16; ++c) EXPECT_EQ(a.evaluated[g][c].genome.genes, b.evaluated[g][c].genome.genes);
  }
  EXPECT_NE(a.evaluated[5][3].genome.genes, other.evaluated[5][3].genome.genes);
}

// the message of `state` restored after `completed` generations
std::string RestoreError(const std::string& name, const nlohmann::json& state, int completed) {
  try {
    MakeLearner(name, Driven::Config(), 11)->Restore(state, completed, "cp.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(PagmoLearnerStateTest, ADamagedOrForeignStateIsRefusedNamingTheField) {
  Driven cmaes("cmaes");
  cmaes.RunTo(3);
  nlohmann::json state = cmaes.learner->State();
  ASSERT_TRUE(state.contains("algorithm"));
  nlohmann::json damaged = state;
  damaged["algorithm"] = state["algorithm"].get<std::string>() + " ";
  EXPECT_EQ(RestoreError("cmaes", damaged, 3),
            "cp.json: field 'learner.algorithm' does not match its 'crc32': the learner's state is damaged");
  // cmaes's state is not sade's
  EXPECT_EQ(RestoreError("sade", state, 3),
            "cp.json: field 'learner.algorithm' is pagmo's CMA-ES: Covariance Matrix Adaptation Evolutionary "
            "Strategy, not this run's sade");
  // another seed is another learner
  try {
    MakeLearner("cmaes", Driven::Config(), 12)->Restore(state, 3, "cp.json");
    ADD_FAILURE() << "accepted the state of another seed";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "cp.json: field 'learner.algorithm' has other settings than this run's cmaes (seed 12)");
  }
  nlohmann::json outside = state;
  outside["population"][3]["x"][kKStep] = 900.0;
  EXPECT_EQ(RestoreError("cmaes", outside, 3),
            "cp.json: field 'learner.population[3].x[12]' = 900 is outside its allowed range [0, 800] (gene 'kStep')");

  Driven pso("pso");
  pso.RunTo(4);
  const nlohmann::json told = pso.learner->State();
  ASSERT_EQ(told.at("told").size(), 3u);
  EXPECT_EQ(RestoreError("pso", told, 4), "accepted");
  EXPECT_EQ(RestoreError("pso", told, 5),
            "cp.json: field 'learner.told' has 3 generations, not one per generation after the first (4)");
  nlohmann::json short_generation = told;
  short_generation["told"][1]["objectives"].erase(0);
  EXPECT_EQ(RestoreError("pso", short_generation, 4),
            "cp.json: field 'learner.told[1].objectives' has 15 values, not one per child (16)");
}

}  // namespace
}  // namespace walkers
