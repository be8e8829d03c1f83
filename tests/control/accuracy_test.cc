// Accuracy is not traded for speed (docs/performance.md, "Accuracy"): on a
// subset of genomes the production settings pass the accuracy criterion
// against 100x tighter tolerances. The walk is chaotic, so each side is an
// ensemble of perturbed evaluations (control/accuracy.h); a single evaluation
// per side passes or fails with the last bits of the arithmetic.
#include "control/accuracy.h"

#include <gtest/gtest.h>

#include "control/start_pose.h"
#include "dynamics/planting.h"

namespace walkers {
namespace {

std::string BenchGenome(const std::string& name) {
  return std::string(WALKERS_SOURCE_DIR) + "/data/genomes/" + name + ".json";
}

// The criterion's ensembles on regular genomes, which it judges without the
// KS test over a set: a regular biped of the authors' and a faller.
TEST(AccuracyTest, ProductionSettingsPassTheCriterionOnRegularGenomes) {
  const EvaluationSettings production;
  const EvaluationSettings reference = HundredTimesTighter(production);
  constexpr int kEnsembleSize = 9;
  for (const char* name : {"bench/authors_case1_biped", "bench/evolved_faller"}) {
    const Genome g = LoadGenome(BenchGenome(name));
    const FitnessEnsemble a =
        EvaluateEnsemble(g, OriginalPreset(), production, kEnsembleSize, nullptr, kAccuracyPerturbation);
    const FitnessEnsemble b =
        EvaluateEnsemble(g, OriginalPreset(), reference, kEnsembleSize, nullptr, kAccuracyPerturbation);
    const AccuracyVerdict v = JudgeAccuracy(a, b);
    EXPECT_TRUE(v.regular) << name << ": reference quartiles " << b.LowerQuartile() << ", " << b.UpperQuartile();
    EXPECT_TRUE(v.fitness_agrees) << name << ": medians " << a.Median() << " and " << b.Median();
    EXPECT_TRUE(v.passes()) << name;
  }
}

TEST(AccuracyTest, TheCriterionJudgesARegularGenomesMedians) {
  FitnessEnsemble reference, production;
  reference.fitness = {10.0, 10.02, 10.01, 9.99, 10.03};
  reference.bipeds = 5;
  production = reference;
  production.fitness = {10.05, 10.06, 10.04, 10.05, 10.07};  // medians 0.4 % apart
  AccuracyVerdict v = JudgeAccuracy(production, reference);
  EXPECT_TRUE(v.regular);
  EXPECT_NEAR(v.median_difference, 0.04 / 10.01, 1e-12);
  EXPECT_TRUE(v.passes());
  production.fitness = {10.2, 10.2, 10.1, 10.3, 10.2};  // 1.9 % apart, outside the reference IQR
  EXPECT_FALSE(JudgeAccuracy(production, reference).passes());
  // more than 1 % apart, but inside the reference's interquartile range
  reference.fitness = {9.5, 9.98, 10.0, 10.17, 10.5};  // quartiles 9.98 and 10.17: 1.9 % of 10
  production.fitness = {10.16, 10.16, 10.16, 10.16, 10.16};
  v = JudgeAccuracy(production, reference);
  EXPECT_TRUE(v.regular);
  EXPECT_GT(v.median_difference, 0.01);
  EXPECT_TRUE(v.passes());
  production.fitness.assign(5, 10.18);  // just outside
  EXPECT_FALSE(JudgeAccuracy(production, reference).passes());
}

TEST(AccuracyTest, APlantedThreePercentBiasFailsARegularGenome) {
  FitnessEnsemble reference;
  reference.fitness = {10.0, 10.01, 10.02, 10.03, 10.04};
  reference.bipeds = 5;
  FitnessEnsemble production = reference;
  for (double& f : production.fitness) f *= 1.03;
  const AccuracyVerdict v = JudgeAccuracy(production, reference);
  EXPECT_TRUE(v.regular);
  EXPECT_NEAR(v.median_difference, 0.03, 1e-12);
  EXPECT_FALSE(v.fitness_agrees);
  EXPECT_FALSE(v.passes());
}

// An irregular genome's fitness is the KS test's, over the set
// (scripts/accuracy.py); here only its other rules decide.
TEST(AccuracyTest, AnIrregularGenomeIsJudgedByItsOtherRules) {
  FitnessEnsemble reference, production;
  reference.fitness = {5.0, 8.0, 9.0, 12.0, 14.0};  // quartiles 8 and 12
  reference.bipeds = production.bipeds = 5;
  production.fitness = {2.0, 4.0, 11.0, 13.0, 20.0};
  AccuracyVerdict v = JudgeAccuracy(production, reference);
  EXPECT_FALSE(v.regular);
  EXPECT_FALSE(v.fitness_agrees);
  EXPECT_TRUE(v.passes());
  // the majority's gait and fall verdict
  production.bipeds = 2;
  v = JudgeAccuracy(production, reference);
  EXPECT_FALSE(v.gait_agrees);
  EXPECT_FALSE(v.passes());
  production.falls = 3;
  EXPECT_FALSE(JudgeAccuracy(production, reference).fall_agrees);
}

// A walk made or broken by the integration error fails, whatever the KS test
// over the set would say.
TEST(AccuracyTest, TheCriterionFindsLostAndNumericalWalkers) {
  FitnessEnsemble reference, production;
  reference.bipeds = production.bipeds = 5;
  // the reference walks (median 6); production stalls in 3 of 5
  reference.fitness = {0.5, 0.8, 6.0, 7.0, 8.0};  // quartiles 0.8 and 7
  production.fitness = {0.5, 0.6, 0.9, 7.0, 8.0};
  AccuracyVerdict v = JudgeAccuracy(production, reference);
  EXPECT_FALSE(v.regular);
  EXPECT_TRUE(v.lost_walker);
  EXPECT_FALSE(v.numerical_walker);
  EXPECT_FALSE(v.passes());
  production.fitness = {0.5, 0.6, 6.0, 7.0, 8.0};  // 2 of 5 stall: no majority
  v = JudgeAccuracy(production, reference);
  EXPECT_FALSE(v.lost_walker);
  EXPECT_TRUE(v.passes());
  production.fitness = {0.5, 1.0, 7.0, 8.0};  // half is no majority; 1.0 counts as stalled
  EXPECT_FALSE(JudgeAccuracy(production, reference).lost_walker);
  production.fitness = {0.5, 1.0, 1.0, 8.0};
  EXPECT_TRUE(JudgeAccuracy(production, reference).lost_walker);

  // the reverse: the reference stalls (median 0.7), production walks in 4 of 5
  reference.fitness = {0.5, 0.6, 0.7, 6.0, 7.0};  // quartiles 0.6 and 6
  production.fitness = {0.5, 5.5, 6.0, 6.5, 7.0};
  v = JudgeAccuracy(production, reference);
  EXPECT_FALSE(v.regular);
  EXPECT_TRUE(v.numerical_walker);
  EXPECT_FALSE(v.lost_walker);
  EXPECT_FALSE(v.passes());
  production.fitness = {0.5, 0.6, 4.9, 6.5, 7.0};  // 4.9 is no walker: 2 of 5
  v = JudgeAccuracy(production, reference);
  EXPECT_FALSE(v.numerical_walker);
  EXPECT_TRUE(v.passes());
  // a reference median between the two thresholds is neither
  reference.fitness = {2.0, 3.0, 3.0, 3.0, 4.0};
  production.fitness = {0.0, 0.0, 0.0, 9.0, 9.0};
  v = JudgeAccuracy(production, reference);
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

  // one evaluation with the start pose's trunk raised by `raise` [m]
  EvaluationResult EvaluateRaised(double raise) const {
    EvaluationSettings member = settings_;
    member.start_trunk_raise = raise;
    return Evaluate(genome_, OriginalPreset(), member);
  }

  Genome genome_;
  EvaluationSettings settings_;
};

TEST_F(EnsembleTest, AccuracyMembersDifferOnlyInTheStartPose) {
  constexpr int kSize = 25;
  const double step = kAccuracyPerturbation.step;
  const EvaluationSettings reference = HundredTimesTighter(settings_);
  for (int k = 0; k < kSize; ++k) {
    const EvaluationSettings member = EnsembleMemberSettings(settings_, kSize, k, kAccuracyPerturbation);
    EXPECT_EQ(member.start_trunk_raise, (k - 12) * step);
    EXPECT_EQ(member.integrator.relative_tolerance, settings_.integrator.relative_tolerance);
    // the reference's members are moved by as much
    const EvaluationSettings tight = EnsembleMemberSettings(reference, kSize, k, kAccuracyPerturbation);
    EXPECT_EQ(tight.start_trunk_raise, member.start_trunk_raise);
    EXPECT_EQ(tight.integrator.relative_tolerance, reference.integrator.relative_tolerance);
    // the re-scores' ensembles leave the start alone
    const EvaluationSettings rescore = EnsembleMemberSettings(settings_, kSize, k);
    EXPECT_EQ(rescore.start_trunk_raise, 0.0);
    EXPECT_EQ(rescore.integrator.relative_tolerance, settings_.integrator.relative_tolerance * (1.0 + 1e-4 * (k - 12)));
  }
  const FitnessEnsemble e = EvaluateEnsemble(genome_, OriginalPreset(), settings_, 3, nullptr, kAccuracyPerturbation);
  ASSERT_EQ(e.fitness.size(), 3u);
  const std::vector<EvaluationResult> members = {EvaluateRaised(-step), Evaluate(genome_, OriginalPreset(), settings_),
                                                 EvaluateRaised(step)};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(e.fitness[k], members[k].fitness) << k;
    EXPECT_EQ(e.cvode_steps[k], static_cast<double>(members[k].integrator_stats.steps)) << k;
  }
  // a raise changes the walk's arithmetic
  EXPECT_NE(members[0].distance, members[2].distance);
}

TEST(AccuracyTest, ARaisedStartIsHigherAndStillOnTheWelds) {
  const Model model = BuildModel(BodyOf(LoadGenome(BenchGenome("default"))));
  const State start = StartState(model);
  constexpr double kRaise = 1e-6;  // [m]
  const State raised = StartState(model, kRaise);
  // the projection onto the welds keeps a part of the raise, spread over the
  // trunk and the joints (about 8 % of it for this genome)
  EXPECT_GT(raised.q(kY), start.q(kY));
  EXPECT_GT((raised.q - start.q).norm(), 0.01 * kRaise);
  EXPECT_LT((raised.q - start.q).norm(), kRaise);
  State projected = raised;
  ASSERT_TRUE(ProjectOntoWelds(model, StartWelds(model), &projected));
  EXPECT_LT((projected.q - raised.q).norm(), 1e-12);
  EXPECT_EQ(raised.v, Vec9::Zero());
  EXPECT_EQ(StartState(model, 0.0).q, start.q);
}

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
  marked.outcome = Outcome::kFell;
  marked.gait = Gait::kTripod;
  const FitnessEnsemble e = Ensemble(3, &marked);
  EXPECT_EQ(e.fitness, (std::vector<double>{evaluated.fitness[0], 123.0, evaluated.fitness[2]}));
  EXPECT_EQ(e.falls, evaluated.falls + (plain.outcome == Outcome::kFell ? 0 : 1));
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
