#include "evolve/scaffold.h"

#include <gtest/gtest.h>

#include "files/errors.h"

namespace walkers {
namespace {

double Ceiling(ScaffoldCase c, const Preset& preset, int generation, double ave, double init_f) {
  return MakeScaffold(c, preset)->Ceiling({generation, ave, init_f});
}

TEST(ScaffoldTest, FreeKeepsTheBodysOwnCeiling) {
  for (int g : {0, 1000, 3999}) EXPECT_DOUBLE_EQ(Ceiling(ScaffoldCase::kFree, OriginalPreset(), g, 20.0, 5.0), 0.9);
}

TEST(ScaffoldTest, TimeConstrainedStepsOfEquationSeven) {
  for (const Preset& preset : {PaperPreset(), OriginalPreset()}) {
    auto at = [&](int g) { return Ceiling(ScaffoldCase::kTime, preset, g, 1.0, 1.0); };
    EXPECT_DOUBLE_EQ(at(0), 0.9);
    EXPECT_DOUBLE_EQ(at(499), 0.9);
    EXPECT_NEAR(at(500), 0.7, 1e-15);
    EXPECT_NEAR(at(1000), 0.5, 1e-15);
    EXPECT_NEAR(at(1999), 0.3, 1e-15);
    EXPECT_NEAR(at(2000), 0.1, 1e-15);
    EXPECT_NEAR(at(3999), 0.1, 1e-15);
  }
}

TEST(ScaffoldTest, PerformanceBasedEquationEightUnderThePaperPreset) {
  const double init_f = 4.9;
  EXPECT_NEAR(Ceiling(ScaffoldCase::kPerformance, PaperPreset(), 10, init_f, init_f), 0.7, 1e-15);
  EXPECT_NEAR(Ceiling(ScaffoldCase::kPerformance, PaperPreset(), 10, 3 * init_f, init_f), 0.3, 1e-15);
  // never below the floor
  EXPECT_DOUBLE_EQ(Ceiling(ScaffoldCase::kPerformance, PaperPreset(), 10, 10 * init_f, init_f), 0.05);
}

TEST(ScaffoldTest, PerformanceBasedAuthorsFormulaUnderTheOriginalPreset) {
  const double init_f = 5.31;
  auto at = [&](double ratio) { return Ceiling(ScaffoldCase::kPerformance, OriginalPreset(), 10, ratio * init_f, init_f); };
  EXPECT_NEAR(at(1.0), 0.7, 1e-15);   // 0.9/1 - 0.2
  EXPECT_NEAR(at(3.0), 0.1, 1e-15);   // 0.9/3 - 0.2
  EXPECT_NEAR(at(4.0), 0.025, 1e-15); // below the body gene's floor of 0.05: allowed
  EXPECT_DOUBLE_EQ(at(5.0), 0.01);    // 0.18 - 0.2 < 0: clamped, never below 0.01
  // best three below InitF (generation 0 holds the default and two weaker
  // mutants): the formula gives more than 0.9; the scaffold never lengthens
  EXPECT_DOUBLE_EQ(at(0.4), 0.9);     // 0.9/0.4 - 0.2 = 2.05
  EXPECT_NEAR(at(0.9), 0.8, 1e-15);   // 0.9/0.9 - 0.2
}

TEST(ScaffoldTest, PerformanceBasedWaitsForProgressToMeasure) {
  for (const Preset& preset : {PaperPreset(), OriginalPreset()}) {
    EXPECT_DOUBLE_EQ(Ceiling(ScaffoldCase::kPerformance, preset, 5, -1.0, 4.0), 0.9);  // nothing walks yet
    EXPECT_DOUBLE_EQ(Ceiling(ScaffoldCase::kPerformance, preset, 5, 4.0, 0.0), 0.9);   // no InitF
    // the run starts the measure at InitF, as the authors' evolver did: 0.7 for generation 0
    const double init_f = kAuthorsInitialFitness;
    EXPECT_NEAR(Ceiling(ScaffoldCase::kPerformance, preset, 0, init_f, init_f), 0.7, 1e-15);
  }
}

TEST(ScaffoldTest, CasesByName) {
  EXPECT_EQ(ScaffoldCaseByName("time"), ScaffoldCase::kTime);
  EXPECT_STREQ(ScaffoldCaseName(ScaffoldCase::kPerformance), "performance");
  try {
    ScaffoldCaseByName("scaffolded");
    FAIL() << "accepted an unknown case";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "unknown case 'scaffolded': allowed values are free, time, performance");
  }
}

TEST(ScaffoldTest, TheListHoldsEachScaffoldOnceInThePapersOrder) {
  const std::vector<ScaffoldSpec>& list = Scaffolds();
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(ScaffoldCaseNames(), (std::vector<std::string>{"free", "time", "performance"}));
  for (const ScaffoldSpec& spec : list) {
    EXPECT_EQ(&ScaffoldSpecOf(spec.id), &spec);
    EXPECT_EQ(MakeScaffold(spec.id, OriginalPreset())->id(), spec.id) << spec.name;
    EXPECT_EQ(spec.number(), static_cast<int>(&spec - list.data()) + 1);
  }
  EXPECT_STREQ(list[1].label, "time-constrained");
  // the authors' case-2 evolver draws halfBodyX again once per child, the others after every mutated gene
  EXPECT_EQ(list[1].authors_body_redraw, AuthorsBodyRedraw::kOnceAtTheEnd);
  EXPECT_EQ(list[0].authors_body_redraw, AuthorsBodyRedraw::kAfterEveryMutatedGene);
  EXPECT_EQ(list[2].authors_body_redraw, AuthorsBodyRedraw::kAfterEveryMutatedGene);
  // the paper's runs: two of case 2's three ended as tripods
  EXPECT_EQ(list[1].paper_tripod_finals, 2);
  EXPECT_EQ(list[0].paper_tripod_finals + list[2].paper_tripod_finals, 0);
}

}  // namespace
}  // namespace walkers
