#include "evolve/individual.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "tests/evolve/individuals.h"

namespace walkers {
namespace {

using testing::WithFitness;

TEST(ArchiveTest, KeepsTheBestSixteenOverAllGenerations) {
  Archive archive(16);
  std::vector<double> all;
  for (int g = 0; g < 5; ++g) {
    std::vector<Individual> children;
    for (int c = 0; c < 16; ++c) {
      const double f = std::sin(7.0 * g + 3.0 * c) * 10.0;  // scattered over generations
      children.push_back(WithFitness(g, c, f));
      all.push_back(f);
    }
    archive.Merge(children);
  }
  std::sort(all.rbegin(), all.rend());
  ASSERT_EQ(archive.members().size(), 16u);
  for (int i = 0; i < 16; ++i) EXPECT_DOUBLE_EQ(archive.members()[i].fitness(), all[i]) << i;
  EXPECT_DOUBLE_EQ(archive.AverageOfBest(3), (all[0] + all[1] + all[2]) / 3.0);
  std::set<int> generations;
  for (const Individual& m : archive.members()) generations.insert(m.generation);
  EXPECT_GT(generations.size(), 1u) << "the best come from several generations";
}

TEST(ArchiveTest, EqualFitnessKeepsTheOlderIndividual) {
  Archive archive(2);
  archive.Merge({WithFitness(0, 0, 5.0), WithFitness(0, 1, 1.0)});
  archive.Merge({WithFitness(1, 0, 5.0), WithFitness(1, 1, 5.0)});
  EXPECT_EQ(archive.members()[0].id(), "0/0");
  EXPECT_EQ(archive.members()[1].id(), "1/0");
}

// A lineage is written as evaluations.csv's `parents` column and the
// archive's "parents" have always spelt it, and read back to the same value.
TEST(LineageTest, ItsTextIsTheFilesAndReadsBackTheSame) {
  using A = Lineage::Admission;
  const std::pair<Lineage, std::string> cases[] = {
      {Lineage{}, ""},
      {Lineage::Of({{0, 0}}), "0/0"},
      {Lineage::Of({{12, 3}, {7, 15}}), "12/3+7/15"},
      {Lineage::ProposedBy("cmaes"), "cmaes"},
      {Lineage{{}, "external", {A::kClamped}}, "external clamped"},
      {Lineage{{{4, 2}}, "", {A::kRedrawn}}, "4/2 redrawn"},
      {Lineage{{}, "external", {A::kClamped, A::kRedrawn, A::kClamped}}, "external clamped redrawn clamped"},
  };
  for (const auto& [lineage, text] : cases) {
    EXPECT_EQ(lineage.Text(), text);
    const std::optional<Lineage> back = Lineage::FromText(text);
    ASSERT_TRUE(back.has_value()) << text;
    EXPECT_EQ(*back, lineage) << text;
  }
}

TEST(LineageTest, TextThatIsNoLineageIsRefused) {
  for (const char* text :
       {"1/2+", "1/2/3", "+1/2", "01/2", "1/2 clamp", "cmaes  redrawn", "x redrawn ", "1/99999999999"}) {
    EXPECT_FALSE(Lineage::FromText(text).has_value()) << text;
  }
}

}  // namespace
}  // namespace walkers
