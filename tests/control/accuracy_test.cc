// Accuracy is not traded for speed (docs/performance.md, "Accuracy"): on a
// subset of the benchmark genomes, the production settings' fitness agrees
// with the same evaluation at 100x tighter tolerances, and the gait class and
// fall verdict agree. The walk is chaotic, so each side is a small ensemble of
// perturbed evaluations (control/accuracy.h) and the medians are compared; a
// single evaluation per side passes or fails with the last bits of the
// arithmetic. The subset holds the walkers whose fitness the tight tolerances
// do pin down (walkers with a regular gait, and a faller); for the chaotic
// ones no tolerance does, and docs/performance.md shows their spread.
#include "control/accuracy.h"

#include <gtest/gtest.h>

namespace walkers {
namespace {

std::string BenchGenome(const std::string& name) {
  return std::string(WALKERS_SOURCE_DIR) + "/data/genomes/" + name + ".json";
}

TEST(AccuracyTest, ProductionSettingsAgreeWithHundredTimesTighterTolerances) {
  const EvaluationSettings production;
  const EvaluationSettings tight = HundredTimesTighter(production);
  constexpr int kEnsembleSize = 9;
  struct Case {
    const char* name;
    bool regular;  // a regular gait: every perturbed evaluation scores the same
  };
  std::vector<double> differences;
  for (const Case& c : {Case{"authors/archive_case3_06_13_00_02_04_2", true},
                        Case{"authors/archive_case3_06_13_20_20_41_2", true}, Case{"default", false},
                        Case{"bench/evolved_faller", false}}) {
    const Genome g = LoadGenome(BenchGenome(c.name));
    const FitnessEnsemble a = EvaluateEnsemble(g, OriginalPreset(), production, kEnsembleSize);
    const FitnessEnsemble b = EvaluateEnsemble(g, OriginalPreset(), tight, kEnsembleSize);
    // the majority's gait and fall verdict
    EXPECT_EQ(2 * a.bipeds > kEnsembleSize, 2 * b.bipeds > kEnsembleSize) << c.name;
    EXPECT_EQ(2 * a.falls > kEnsembleSize, 2 * b.falls > kEnsembleSize) << c.name;
    differences.push_back(RelativeFitnessDifference(a.Median(), b.Median()));
    // the integration error must not decide a regular walker's steps: at an
    // absolute velocity tolerance of 1e-2 some members of this ensemble
    // scored 5 % more than the rest
    if (c.regular) {
      EXPECT_LT(RelativeFitnessDifference(a.Min(), b.Median()), 0.01) << c.name;
      EXPECT_LT(RelativeFitnessDifference(a.Max(), b.Median()), 0.01) << c.name;
    }
  }
  EXPECT_LT(Median(differences), 0.01) << "median relative fitness difference";
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
