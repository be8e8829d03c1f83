#include "evolve/genetic_algorithm.h"

#include <gtest/gtest.h>

#include "files/errors.h"
#include "tests/evolve/individuals.h"

namespace walkers {
namespace {

using testing::WithFitness;

class BreedTest : public ::testing::Test {
 protected:
  GeneticAlgorithmConfig config_;
  MutationRules rules_{0.9, BodyGeneMutation::kLikeEveryGene, AuthorsBodyRedraw::kAfterEveryMutatedGene};

  Archive FullArchive() {
    Archive archive(16);
    std::vector<Individual> members;
    for (int c = 0; c < 16; ++c) members.push_back(WithFitness(3, c, 20.0 - c));
    archive.Merge(members);
    return archive;
  }
};

TEST_F(BreedTest, GenerationZeroIsTheDefaultAndItsMutants) {
  std::set<GenomeKey> seen;
  const std::vector<Individual> children = Breed(config_, {1, 0, 0.9, rules_}, Archive(16), &seen);
  ASSERT_EQ(children.size(), 16u);
  EXPECT_EQ(children[0].genome.genes, DefaultGenome().genes);
  EXPECT_EQ(children[0].lineage.Text(), "");
  for (int c = 1; c < 16; ++c) {
    EXPECT_EQ(children[c].lineage.Text(), "0/0");
    EXPECT_NE(children[c].genome.genes, DefaultGenome().genes);
  }
  EXPECT_EQ(seen.size(), 16u);
}

TEST_F(BreedTest, ChildrenComeFromTheirOwnStreamsAndCrossoverIsTheMeanBeforeMutation) {
  const Archive archive = FullArchive();
  std::set<GenomeKey> seen;
  const int g = 4;
  const std::vector<Individual> children = Breed(config_, {9, g, 0.9, rules_}, archive, &seen);
  ASSERT_EQ(children.size(), 16u);
  auto parent = [&](const std::string& id) -> const Genome& {
    for (const Individual& m : archive.members()) {
      if (m.id() == id) return m.genome;
    }
    throw std::runtime_error("no parent " + id);
  };
  for (int c = 0; c < 16; ++c) {
    Random rng(9, g, c);
    const std::string p = children[c].lineage.Text();
    Genome expected;
    if (c < config_.mutation_children) {
      ASSERT_EQ(p.find('+'), std::string::npos);
      expected = Mutate(parent(p), 0.9, rules_, &rng);
    } else {
      const auto plus = p.find('+');
      ASSERT_NE(plus, std::string::npos) << "crossover children have two parents";
      EXPECT_NE(p.substr(0, plus), p.substr(plus + 1)) << "drawn without replacement";
      expected = Mutate(Crossover(parent(p.substr(0, plus)), parent(p.substr(plus + 1))), 0.9, rules_, &rng);
    }
    EXPECT_EQ(children[c].genome.genes, expected.genes) << "child " << c;
  }
  // the ten mutation parents are distinct: drawn from one shuffle without replacement
  std::set<std::string> mutation_parents;
  for (int c = 0; c < 10; ++c) mutation_parents.insert(children[c].lineage.Text());
  EXPECT_EQ(mutation_parents.size(), 10u);
}

TEST_F(BreedTest, ADuplicateIsDrawnAgain) {
  const Archive archive = FullArchive();
  // what child 0 would be: its parent and first draw
  std::set<GenomeKey> probe;
  const std::vector<Individual> first = Breed(config_, {5, 7, 0.9, rules_}, archive, &probe);
  // the same breeding, with child 0's first draw already seen
  std::set<GenomeKey> seen = {KeyOf(first[0].genome)};
  const std::vector<Individual> again = Breed(config_, {5, 7, 0.9, rules_}, archive, &seen);
  EXPECT_NE(KeyOf(again[0].genome), KeyOf(first[0].genome));
  EXPECT_EQ(again[0].lineage.Text(), first[0].lineage.Text());
  // it is the second draw of the same stream
  Random rng(5, 7, 0);
  const Genome& p = [&]() -> const Genome& {
    for (const Individual& m : archive.members()) {
      if (m.id() == first[0].lineage.Text()) return m.genome;
    }
    throw std::runtime_error("parent");
  }();
  Mutate(p, 0.9, rules_, &rng);
  EXPECT_EQ(again[0].genome.genes, Mutate(p, 0.9, rules_, &rng).genes);
  // other children are unaffected
  EXPECT_EQ(again[5].genome.genes, first[5].genome.genes);
}

TEST(GeneticAlgorithmConfigTest, RejectsImpossibleSizes) {
  GeneticAlgorithmConfig c;
  c.mutation_children = 20;
  EXPECT_THROW(c.Validate(), InputError);
  c = GeneticAlgorithmConfig{};
  c.archive_size = 1;
  try {
    c.Validate("run/config.json");
    FAIL() << "accepted an archive of 1";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "run/config.json: archive_size = 1 is outside its allowed range [2, 100000]");
  }
  c = GeneticAlgorithmConfig{};
  EXPECT_NO_THROW(c.Validate());
  EXPECT_EQ(c.crossover_children(), 6);
}

}  // namespace
}  // namespace walkers
