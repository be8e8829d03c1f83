// Accuracy is not traded for speed (docs/performance.md, "Accuracy"): on a
// subset of genomes the production settings pass the accuracy criterion
// against 100x tighter tolerances. The walk is chaotic, so each side is an
// ensemble of perturbed evaluations (control/accuracy.h); a single evaluation
// per side passes or fails with the last bits of the arithmetic. The subset
// holds a regular biped of the authors', the chaotic default genome and a
// faller.
#include "control/accuracy.h"

#include <gtest/gtest.h>

namespace walkers {
namespace {

std::string BenchGenome(const std::string& name) {
  return std::string(WALKERS_SOURCE_DIR) + "/data/genomes/" + name + ".json";
}

TEST(AccuracyTest, ProductionSettingsPassTheCriterionOnASubset) {
  const EvaluationSettings production;
  const EvaluationSettings tight = HundredTimesTighter(production);
  constexpr int kEnsembleSize = 9;
  for (const char* name : {"authors/archive_case3_06_13_20_20_41_2", "default", "bench/evolved_faller"}) {
    const Genome g = LoadGenome(BenchGenome(name));
    const FitnessEnsemble a = EvaluateEnsemble(g, OriginalPreset(), production, kEnsembleSize);
    const FitnessEnsemble b = EvaluateEnsemble(g, OriginalPreset(), tight, kEnsembleSize);
    const AccuracyVerdict v = JudgeAccuracy(a, b);
    EXPECT_TRUE(v.fitness_agrees) << name << (v.regular ? ": regular, medians " : ": irregular, medians ")
                                  << a.Median() << " and " << b.Median();
    EXPECT_TRUE(v.gait_agrees) << name;
    EXPECT_TRUE(v.fall_agrees) << name;
  }
}

TEST(AccuracyTest, TheCriterionJudgesRegularAndIrregularWalkers) {
  FitnessEnsemble tight, production;
  tight.fitness = {10.0, 10.02, 10.01, 9.99, 10.03};
  tight.bipeds = 5;
  production = tight;
  production.fitness = {10.05, 10.06, 10.04, 10.05, 10.07};  // medians 0.4 % apart
  AccuracyVerdict v = JudgeAccuracy(production, tight);
  EXPECT_TRUE(v.regular);
  EXPECT_NEAR(v.median_difference, 0.04 / 10.01, 1e-12);
  EXPECT_TRUE(v.passes());
  production.fitness = {10.2, 10.2, 10.1, 10.3, 10.2};  // 1.9 % apart
  EXPECT_FALSE(JudgeAccuracy(production, tight).passes());
  // an irregular walker: only the median inside the tight interquartile range counts
  tight.fitness = {5.0, 8.0, 9.0, 12.0, 14.0};  // quartiles 8 and 12
  production.fitness = {2.0, 4.0, 11.0, 13.0, 20.0};
  v = JudgeAccuracy(production, tight);
  EXPECT_FALSE(v.regular);
  EXPECT_TRUE(v.fitness_agrees);
  production.fitness = {2.0, 4.0, 7.0, 13.0, 20.0};
  EXPECT_FALSE(JudgeAccuracy(production, tight).fitness_agrees);
  // the majority's gait and fall verdict
  production.bipeds = 2;
  EXPECT_FALSE(JudgeAccuracy(production, tight).gait_agrees);
  production.falls = 3;
  EXPECT_FALSE(JudgeAccuracy(production, tight).fall_agrees);
}

// A walk made or broken by the integration error fails even where the
// median's place in the tight interquartile range would let it pass.
TEST(AccuracyTest, TheCriterionFindsLostAndNumericalWalkers) {
  FitnessEnsemble tight, production;
  tight.bipeds = production.bipeds = 5;
  // the tight ensemble walks (median 6); production stalls in 3 of 5
  tight.fitness = {0.5, 0.8, 6.0, 7.0, 8.0};  // quartiles 0.8 and 7
  production.fitness = {0.5, 0.6, 0.9, 7.0, 8.0};
  AccuracyVerdict v = JudgeAccuracy(production, tight);
  EXPECT_TRUE(v.fitness_agrees);  // median 0.9 inside [0.8, 7]
  EXPECT_TRUE(v.lost_walker);
  EXPECT_FALSE(v.numerical_walker);
  EXPECT_FALSE(v.passes());
  production.fitness = {0.5, 0.6, 6.0, 7.0, 8.0};  // 2 of 5 stall: no majority
  v = JudgeAccuracy(production, tight);
  EXPECT_FALSE(v.lost_walker);
  EXPECT_TRUE(v.passes());
  production.fitness = {0.5, 1.0, 7.0, 8.0};  // half is no majority; 1.0 counts as stalled
  EXPECT_FALSE(JudgeAccuracy(production, tight).lost_walker);
  production.fitness = {0.5, 1.0, 1.0, 8.0};
  EXPECT_TRUE(JudgeAccuracy(production, tight).lost_walker);

  // the reverse: the tight ensemble stalls (median 0.7), production walks in 4 of 5
  tight.fitness = {0.5, 0.6, 0.7, 6.0, 7.0};  // quartiles 0.6 and 6
  production.fitness = {0.5, 5.5, 6.0, 6.5, 7.0};
  v = JudgeAccuracy(production, tight);
  EXPECT_TRUE(v.fitness_agrees);  // median 6 inside [0.6, 6]
  EXPECT_TRUE(v.numerical_walker);
  EXPECT_FALSE(v.lost_walker);
  EXPECT_FALSE(v.passes());
  production.fitness = {0.5, 0.6, 4.9, 6.5, 7.0};  // 4.9 is no walker: 2 of 5
  v = JudgeAccuracy(production, tight);
  EXPECT_FALSE(v.numerical_walker);
  EXPECT_TRUE(v.passes());
  // a tight median between the two thresholds is neither
  tight.fitness = {2.0, 3.0, 3.0, 3.0, 4.0};
  production.fitness = {0.0, 0.0, 0.0, 9.0, 9.0};
  v = JudgeAccuracy(production, tight);
  EXPECT_FALSE(v.lost_walker);
  EXPECT_FALSE(v.numerical_walker);
}

TEST(AccuracyTest, QuantilesInterpolateBetweenOrderStatistics) {
  EXPECT_EQ(Quantile({}, 0.5), 0.0);
  EXPECT_EQ(Quantile({4.0, 1.0, 3.0, 2.0}, 0.25), 1.75);
  EXPECT_EQ(Quantile({4.0, 1.0, 3.0, 2.0}, 0.5), 2.5);
  EXPECT_EQ(Quantile({4.0, 1.0, 3.0, 2.0}, 1.0), 4.0);
  EXPECT_EQ(Quantile({7.0}, 0.75), 7.0);
}

// Ensembles of a short walk of a regular walker.
class EnsembleTest : public ::testing::Test {
 protected:
  EnsembleTest() : genome_(LoadGenome(BenchGenome("authors/archive_case3_06_13_00_02_04_2"))) { settings_.duration = 3.0; }

  FitnessEnsemble Ensemble(int size, const EvaluationResult* unperturbed = nullptr) const {
    return EvaluateEnsemble(genome_, OriginalPreset(), settings_, size, unperturbed);
  }
  // one evaluation with the relative tolerance scaled by `factor`
  double FitnessAtScaledTolerance(double factor) const {
    EvaluationSettings member = settings_;
    member.integrator.relative_tolerance *= factor;
    return Evaluate(genome_, OriginalPreset(), member).fitness;
  }

  Genome genome_;
  EvaluationSettings settings_;
};

TEST_F(EnsembleTest, MembersDifferOnlyInTheRelativeTolerance) {
  const FitnessEnsemble e = Ensemble(3);
  ASSERT_EQ(e.fitness.size(), 3u);
  // the middle member is the settings themselves
  EXPECT_EQ(e.fitness[1], Evaluate(genome_, OriginalPreset(), settings_).fitness);
  EXPECT_EQ(e.fitness[0], FitnessAtScaledTolerance(1.0 - 1e-4));
  EXPECT_EQ(e.fitness[2], FitnessAtScaledTolerance(1.0 + 1e-4));
  EXPECT_LE(e.Min(), e.Median());
  EXPECT_LE(e.Median(), e.Max());
}

TEST_F(EnsembleTest, EvenEnsemblesAreSymmetricAboutTheSettings) {
  const FitnessEnsemble e = Ensemble(2);
  ASSERT_EQ(e.fitness.size(), 2u);
  EXPECT_EQ(e.fitness[0], FitnessAtScaledTolerance(1.0 - 0.5e-4));
  EXPECT_EQ(e.fitness[1], FitnessAtScaledTolerance(1.0 + 0.5e-4));
}

TEST_F(EnsembleTest, AnOddEnsembleTakesItsMiddleMemberFromAGivenEvaluation) {
  const EvaluationResult plain = Evaluate(genome_, OriginalPreset(), settings_);
  const FitnessEnsemble evaluated = Ensemble(3);
  const FitnessEnsemble reused = Ensemble(3, &plain);
  EXPECT_EQ(reused.fitness, evaluated.fitness);
  EXPECT_EQ(reused.bipeds, evaluated.bipeds);
  EXPECT_EQ(reused.falls, evaluated.falls);

  // a result no evaluation of this genome gives shows that it is used, and
  // only for the middle member
  EvaluationResult marked = plain;
  marked.fitness = 123.0;
  marked.fell = true;
  marked.gait = Gait::kTripod;
  const FitnessEnsemble e = Ensemble(3, &marked);
  EXPECT_EQ(e.fitness, (std::vector<double>{evaluated.fitness[0], 123.0, evaluated.fitness[2]}));
  EXPECT_EQ(e.falls, evaluated.falls + (plain.fell ? 0 : 1));
  EXPECT_EQ(e.bipeds, evaluated.bipeds - (plain.gait == Gait::kBiped ? 1 : 0));
  // an even ensemble has no member at the settings themselves
  EXPECT_EQ(Ensemble(2, &marked).fitness, Ensemble(2).fitness);
}

TEST(AccuracyTest, AnEnsembleIsPinnedWhenEveryMemberIsNearItsMedian) {
  FitnessEnsemble e;
  e.fitness = {10.0, 10.05, 9.96};
  EXPECT_NEAR(e.WorstDifferenceFrom(10.0), 0.005, 1e-15);  // 10.05 - 10 rounds
  EXPECT_TRUE(e.Pinned(0.01));
  EXPECT_FALSE(e.Pinned(0.004));
  e.fitness.push_back(11.0);  // one member 10 % off
  EXPECT_FALSE(e.Pinned(0.01));
  // fitnesses near zero compare absolutely, as RelativeFitnessDifference does
  e.fitness = {-1.0, -1.0, -1.0};
  EXPECT_TRUE(e.Pinned(0.0));
  e.fitness = {0.1, 0.2};
  EXPECT_DOUBLE_EQ(e.WorstDifferenceFrom(0.0), 0.2);
  EXPECT_EQ(FitnessEnsemble{}.WorstDifferenceFrom(5.0), 0.0);
}

TEST(AccuracyTest, MedianOfEvenAndOddCounts) {
  EXPECT_EQ(Median({}), 0.0);
  EXPECT_EQ(Median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(Median({4.0, 1.0, 3.0, 2.0}), 2.5);
}

}  // namespace
}  // namespace walkers
